#pragma once
// Viscous Burgers v_t + v v_x = nu v_xx on a periodic domain by the Hopf-Cole
// transform (Hopf 1950; Cole 1951; Whitham, "Linear and Nonlinear Waves", §4.4):
//
//     v = -2 nu d/dx ln theta,   theta_t = nu theta_xx,   theta(x, 0) = exp(-Psi0(x) / 2 nu),
//
// Psi0' = v0. A non-zero mean velocity U makes Psi0 non-periodic, so the heat
// equation is solved for w = v - U in the frame moving with U and shifted back:
// v(x, t) = U + w(x - U t, t) (Galilean invariance of Burgers).
//
// Cell averages are exact given theta at the cell edges:
//     (1/h) int_a^b v dx = U - 2 nu (ln theta(b - U t) - ln theta(a - U t)) / h.
// The initial data enter through their cell averages (cell_averages()), so Psi0 is
// exact at the edges and piecewise linear between them.
//
// Two ways to get ln theta at the edges:
//  * fft: theta0 sampled at the edges, the heat equation solved exactly for its
//    trigonometric interpolant (multiply mode k by exp(-nu k^2 t)), the shift
//    applied as a phase. O(n log n). Roundoff: FFTW's absolute error ~ eps log2(n)
//    times max theta0 (= 1 after normalisation), so the relative error of theta is
//    ~ eps log2(n) / theta(x, t) and grows like exp(DeltaPsi / 2 nu): with
//    DeltaPsi / 2 nu ~ 36 all digits are gone, long before exp overflows (~709).
//    The path returns that bound on the velocity error, so failure is detected.
//  * log (heat kernel): ln theta(y) = logsumexp_q [-(y - q)^2 / 4 nu t - Psi0(q) / 2 nu]
//    + ln(dq / sqrt(4 pi nu t)), the sum over the unrolled periodic nodes q,
//    centred on the Hopf-Lax minimiser q*(y) of (y - q)^2 / 2t + Psi0(q) and
//    restricted to the window where the exponent is within 40 of its maximum
//    (e^-40 < 1e-17). The window is found from the lower convex hull of
//    Psi0(q) + q^2 / 2t (the Legendre-transform picture of Hopf-Lax), so the cost
//    is O(n * window). Exact in exponent range for any nu > 0.
//
// Density: Hopf-Cole gives the velocity only; the continuity equation has no
// closed form at nu > 0, so solve_hopf_cole returns rho empty and says so in
// method_note (cvode / arkode carry rho).
#include <cstddef>
#include <string>
#include <vector>

#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/progress.hpp"

namespace shockgas::continuum {

// Psi0 of the moving-frame velocity w0 = v0 - U at the n cell edges q_j = j h.
struct MovingFramePotential {
  double length = 1;         // domain length [length]
  double mean_velocity = 0;  // U, mean of v0 [length/time]
  std::vector<double> psi;   // psi_j = int_0^{q_j} (v0 - U) dq [length^2/time], periodic
  double spacing() const { return length / static_cast<double>(psi.size()); }
  double spread() const;  // max psi - min psi [length^2/time]
};

// From the n cell averages of v0 (exact cumulative sums).
MovingFramePotential moving_frame_potential(const std::vector<double>& cell_average_v, double length);

// ln theta at the n points y_j = q_j - shift (j = 0..n-1), up to one additive
// constant common to all j.
struct LogTheta {
  std::vector<double> values;
  double velocity_error_bound = 0;  // fft: roundoff bound on every cell-average v [length/time]
                                    // (infinite if theta lost positivity); log: 0 (no amplification)
  std::size_t nodes_per_cell = 1;   // log: quadrature nodes per cell (refined when sqrt(2 nu t) < 2 h)
};

// The two paths (see the file comment). nu > 0, t > 0.
LogTheta log_theta_fft(const MovingFramePotential& psi0, double nu, double t, double shift);
LogTheta log_theta_kernel(const MovingFramePotential& psi0, double nu, double t, double shift);

// Estimated number of kernel terms the log path sums (n times the window of a
// smooth region, where the hull's curvature is 1/t): its cost, for the path choice.
double log_theta_kernel_terms(const MovingFramePotential& psi0, double nu, double t);

// Cell averages v_i = U - 2 nu (L_{i+1} - L_i) / h, L_n = L_0 (periodic).
std::vector<double> velocity_from_log_theta(const MovingFramePotential& psi0,
                                            const std::vector<double>& log_theta, double nu);

// The solver: cell averages of v at t_end on p.cells cells, path from p.hopf_cole_path.
// With scale = max|v0| (cell averages), the fft result is
//  * accepted if its roundoff bound is <= p.rtol * scale;
//  * never returned if the bound is > 1e-3 * scale (it has lost its digits): a forced
//    fft path throws RunError, auto runs the log path whatever it costs;
//  * in between, auto runs the log path unless that would take more than 2e8 kernel
//    terms (seconds), and keeps the fft result otherwise, saying so in method_note;
//    a forced fft path returns it with the bound in method_note.
// Throws InputError for nu <= 0 (continuum.nu), too few cells (continuum.cells) or
// t_end < 0; RunError if the forced fft path lost its
// digits or any output is non-finite (naming the solver, the cell and the time).
// stats: "spread_over_2nu" (DeltaPsi / 2 nu), "fft_velocity_error_bound" (if fft ran),
// "log_path" (1 if the log path produced the result), "refinement" (log path nodes per cell).
ContinuumResult solve_hopf_cole(const InitialField& f, const ContinuumParams& p, double t_end,
                                const ProgressCallback& progress = {});

// Its registration (registry.hpp).
SolverInfo hopf_cole_solver();

}  // namespace shockgas::continuum
