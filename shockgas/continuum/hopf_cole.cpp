// solve_hopf_cole: input checks, the choice between the fft and log paths, and
// the result. The paths themselves are in hopf_cole_fft.cpp and hopf_cole_kernel.cpp.
#include "shockgas/continuum/hopf_cole.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

constexpr const char* kName = "hopf_cole";  // as registered

void check_input(const ContinuumParams& p, double t_end) {
  require_above("continuum.nu", p.nu, 0.0);
  require(p.cells >= 8, "continuum.cells", p.cells, "an integer >= 8");
  require(std::isfinite(t_end) && t_end >= 0, "continuum.t_end", t_end, "a finite time >= 0");
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

constexpr double kFftDigitsLost = 1e-3;  // fft bound / scale above which it is never returned
constexpr double kLogPathBudget = 2e8;   // kernel terms the log path may take unasked (~seconds)

// The fft path when its roundoff bound allows (see hopf_cole.hpp), else the log
// path. Fills the note and the stats; throws for a forced fft path that lost its digits.
std::vector<double> log_theta_chosen(const MovingFramePotential& psi0, const ContinuumParams& p, double t,
                                     double scale, ContinuumResult& r) {
  const double shift = psi0.mean_velocity * t;
  const std::string spread = "DeltaPsi/2nu = " + to_text(r.stats["spread_over_2nu"], 3);
  const double tolerance = p.rtol * scale;
  if (p.hopf_cole_path != HopfColePath::log) {
    LogTheta fft = log_theta_fft(psi0, p.nu, t, shift);
    const double bound = fft.velocity_error_bound;
    r.stats["fft_velocity_error_bound"] = bound;
    const std::string why =
        spread + "; roundoff bound on v " + to_text(bound, 3) + " vs rtol*max|v0| = " + to_text(tolerance, 3);
    const bool usable = bound <= kFftDigitsLost * scale;
    const double terms = log_theta_kernel_terms(psi0, p.nu, t);
    if (bound <= tolerance) {
      r.method_note = "Hopf-Cole, fft path (" + why + ")";
      return fft.values;
    }
    // The log path is for small nu, where exp(-Psi / 2 nu) spans more than
    // doubles hold. Where it spans less than e (large nu) it meets the same
    // roundoff as the fft path, 2 nu eps / h in v, and without a bound (found:
    // nu = 1e10 gave |v| = 0.02 for a decayed sine): the fft path then stands.
    // A constant v0 (spread 0) the log path solves exactly.
    const double spread_over_2nu = r.stats["spread_over_2nu"];
    const bool log_helps = spread_over_2nu > 1 || spread_over_2nu == 0;
    if (!log_helps && !usable && p.hopf_cole_path == HopfColePath::automatic)
      throw RunError(std::string(kName) + ": nu too large for doubles at t = " + to_text(t, 3) + " (" + why +
                     "): v = -2 nu d/dx log theta loses its digits on both paths");
    if (p.hopf_cole_path == HopfColePath::fft && !usable)
      throw RunError(std::string(kName) + ": the forced fft path lost its digits at t = " + to_text(t, 3) +
                     " (" + why + "); use continuum.hopf_cole_path = \"log\" or \"auto\"");
    if (p.hopf_cole_path == HopfColePath::fft || (usable && (terms > kLogPathBudget || !log_helps))) {
      r.method_note = "Hopf-Cole, fft path above tolerance (" + why + "; the log path would sum ~" +
                      to_text(terms, 3) + " kernel terms)";
      return fft.values;
    }
    r.method_note = "Hopf-Cole, log-domain path: the fft path was rejected (" + why + ")";
  } else {
    r.method_note = "Hopf-Cole, log-domain path (forced; " + spread + ")";
  }
  LogTheta log = log_theta_kernel(psi0, p.nu, t, shift);
  r.stats["log_path"] = 1;
  r.stats["refinement"] = static_cast<double>(log.nodes_per_cell);
  return log.values;
}

// RunError naming the cell and time of the first non-finite entry of v.
void require_finite(const std::vector<double>& v, const std::vector<double>& x, double t) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw RunError(std::string(kName) + ": non-finite velocity in cell " + std::to_string(i) +
                     " (x = " + to_text(x[i], 3) + ") at t = " + to_text(t, 3));
}

}  // namespace

ContinuumResult solve_hopf_cole(const InitialField& f, const ContinuumParams& p, double t_end,
                                const ProgressCallback& progress) {
  check_input(p, t_end);
  const CellAverages initial = cell_averages(f, p.cells);
  ContinuumResult r;
  r.solver = kName;
  r.t = t_end;
  r.length = f.length;
  r.x = cell_centres(f.length, p.cells);
  require_finite(initial.v, r.x, 0.0);
  const MovingFramePotential psi0 = moving_frame_potential(initial.v, f.length);
  r.stats["spread_over_2nu"] = psi0.spread() / (2 * p.nu);
  r.stats["log_path"] = 0;
  if (t_end == 0) {
    r.v = initial.v;
    r.method_note = "Hopf-Cole at t = 0: the initial cell averages";
  } else {
    const double scale = std::max(max_abs(initial.v), 1e-300);
    r.v = velocity_from_log_theta(psi0, log_theta_chosen(psi0, p, t_end, scale, r), p.nu);
  }
  r.method_note += "; density not computed (Hopf-Cole gives v only), rho empty";
  require_finite(r.v, r.x, t_end);
  if (progress) progress(1.0, t_end, 0);
  return r;
}

SolverInfo hopf_cole_solver() {
  SolverInfo s;
  s.name = kName;
  s.summary = "viscous Burgers (velocity only) by the Hopf-Cole transform: FFT, or log-domain heat kernel";
  s.label = s.name + " (viscous, exact)";
  s.colour = "tab:red";
  s.bytes_per_cell = 75;  // peak resident memory at work, measured at 2e4-4e5 cells
  s.viscous = true;
  s.direct_in_time = true;
  s.preflight = [](const InitialField&, const ContinuumParams& p, double t_end) { check_input(p, t_end); };
  s.run = solve_hopf_cole;
  return s;
}

}  // namespace shockgas::continuum
