#pragma once
// Stability scans of `shockgas bench` (docs/performance.md): each runs a method
// past its predicted limit, detects the failure and says what happened. The
// scans are functions of their parameters so that tests can pin the detections.
#include <cstddef>
#include <string>
#include <vector>

#include "shockgas/particles/run_result.hpp"
#include "shockgas/studies/common.hpp"
#include "shockgas/studies/problems.hpp"

namespace shockgas::studies {

// ---- Finite volume against the Courant number ----

// The scheme is stepped here (godunov_scheme.hpp) so that every step is watched.
// A run counts as failed if the total variation of v rises in any step by more
// than 1e-8 TV(v0) (TVD schemes never raise it; rounding is ~1e-14), or v or rho
// turn non-finite or |v| exceeds 10 max|v0| (then it stops: a blow-up). A
// negative density is reported but is not by itself a failure of the velocity.
struct CflPoint {
  double cfl = 0;
  bool failed = false;
  bool blew_up = false;          // stopped: non-finite or |v| > 10 max|v0|
  double max_tv_rise = 0;        // max over steps of (TV_{n+1} - TV_n) / TV_0 [1]
  std::size_t rising_steps = 0;  // steps whose TV rise passed the threshold
  double tv_ratio = 0;           // TV(v) at the end / TV(v0); NaN if it blew up [1]
  double max_ratio = 0;          // max|v| at the end / max|v0|; NaN if it blew up [1]
  double min_rho = 0;            // min density over the run [mass/length]
  double l1 = 0;                 // L1 error against Hopf-Lax at pb.t; NaN if it blew up [length^2/time]
  double t_reached = 0;          // [time]
  std::string what;              // in words
};
// solver: the registered name of godunov or godunov2; limiter: its scene name, for godunov2.
std::vector<CflPoint> cfl_scan(const Problem& pb, const std::string& solver, const std::string& limiter,
                               std::size_t cells, const std::vector<double>& cfls);

// The scan's verdict: the last stable value before the first failure, and the first failure
// (0 if none failed).
struct ScanLimit {
  double last_stable = 0;
  double first_failed = 0;
};
ScanLimit cfl_limit(const std::vector<CflPoint>& points);

// The CSV section (stability_cfl.csv, stability_cfl_limits.csv).
void cfl_stability(const Context& ctx, FailureLog& failures);

// ---- Explicit viscous Burgers against nu and dx ----

struct ViscousPoint {
  double nu = 0;
  std::size_t cells = 0;
  double c = 0;            // dt / (h^2 / 2 nu): 1 is the diffusive limit [1]
  double c_predicted = 0;  // the frozen-coefficient limit 1 / (1 + max|v0| h / 2 nu), in units of h^2/2nu [1]
  bool failed = false;     // blew up, or TV grew by more than 1 %
  double tv_ratio = 0;     // TV at the end / TV(v0) [1]
  std::size_t steps = 0;   // steps taken
};
// Forward Euler from the cell averages of pb.field, `steps` steps of dt = c h^2 / 2 nu.
ViscousPoint explicit_viscous_point(const Problem& pb, double nu, std::size_t cells, double c,
                                    std::size_t steps);

// ---- Hopf-Cole FFT against DeltaPsi / 2 nu ----

struct HopfColePoint {
  double ratio = 0;         // DeltaPsi / 2 nu [1]
  double nu = 0;            // [length^2/time]
  double fft_error = 0;     // max |v_fft - v_log| of the raw FFT path; NaN if non-finite [length/time]
  bool fft_finite = true;   // the raw FFT path gave finite values everywhere
  double fft_bound = 0;     // the path's own roundoff bound [length/time]
  std::string solver_fft;   // what solving hopf_cole on the fft path did: "accepted" or the error
  std::string solver_auto;  // the method_note of path auto
  double log_seconds = 0;   // wall time of the log path [s]
};
// pb at pb.t on `cells` cells with nu = DeltaPsi / (2 ratio).
HopfColePoint hopf_cole_point(const Problem& pb, std::size_t cells, double ratio);

// Roundoff prediction of the header hopf_cole.hpp: the FFT's relative error
// eps log2(n) exp(DeltaPsi / 2 nu) reaches `tolerance` at this ratio.
double hopf_cole_predicted_break(std::size_t cells, double tolerance);

// ---- The particle engine against delta -> 0 ----

// Three particles on a line (x = 0, 1, 2.5; v = 1, 0, -1), delta = 0: collapse
// iff r < 7 - 4 sqrt(3) (McNamara & Young 1992).
particles::RunStop three_particle_stop(double r);

// N particles on a ring (lattice, uniform velocities, realization `seed`),
// delta = 0, bounded by t_end, max_collisions and max_wall_seconds.
particles::RunStop ring_stop(std::size_t N, double r, std::uint64_t seed, double t_end);

// McNamara-Young estimate of the particles a collapse needs: -ln(1 - r) / (1 - r).
double collapse_particles_predicted(double r);

}  // namespace shockgas::studies
