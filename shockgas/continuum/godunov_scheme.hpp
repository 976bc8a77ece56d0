#pragma once
// Conservative finite-volume schemes, generic over the physics (the pattern of
// deal.II step-69's ProblemDescription and of Clawpack's Riemann solvers): the
// code below never sees a flux formula, only a Physics type with
//
//     State                        cell averages of the conserved variables (std::array)
//     State flux(State)            the physical flux F(U)
//     State riemann_flux(L, R)     the numerical (Godunov) flux at an interface
//     double speed(State)          the fastest signal speed of a cell state
//
// Cells [i dx, (i+1) dx), i = 0..n-1, with two ghost cells on each side filled by
// the boundary rule (periodic, or outflow = zero-gradient copies of the edge cell).
// One step is U_i <- U_i - (dt/dx) (F_{i+1/2} - F_{i-1/2}): mass and every other
// conserved variable change only through interface fluxes, so on a periodic domain
// their sums are conserved to rounding.
//
//  * step_godunov: first order, F_{i+1/2} = riemann_flux(U_i, U_{i+1}) (Godunov 1959).
//    Stable (monotone, TVD) for dt max|speed| / dx <= 1.
//  * step_muscl_hancock: second order (van Leer 1979; Toro, "Riemann Solvers and
//    Numerical Methods for Fluid Dynamics", 3rd ed., §14.4): limited slopes per
//    component, face values evolved by half a step with the physical flux, then the
//    Riemann flux between the evolved faces. For linear advection it is Sweby's
//    flux-limited scheme, TVD for Courant numbers in [0, 1] with any limiter in
//    Sweby's region (minmod, van Leer, MC), hence the same bound 1.
//
// The cells may be cut into segments, each with its own ghost cells, filled
// from its neighbours (or by the boundary rule) before a step and then stepped
// by a thread of its own: every cell sees the same old values as in one piece,
// so the cells are the same to the bit for any number of segments (only the
// step's checksum is summed in another order; it only says whether every cell
// is finite).
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/core/progress.hpp"
#include "shockgas/core/thread_team.hpp"

namespace shockgas::continuum {

template <class P>
concept FiniteVolumePhysics = requires(const typename P::State& u) {
  { P::flux(u) } -> std::same_as<typename P::State>;
  { P::riemann_flux(u, u) } -> std::same_as<typename P::State>;
  { P::speed(u) } -> std::convertible_to<double>;
  { P::components } -> std::convertible_to<std::size_t>;
  { P::component_names[0] } -> std::convertible_to<const char*>;  // for error messages
};

// What a step leaves for the time loop: the speed for the next CFL step and the
// sum of every component of every cell (not finite iff some cell is not finite).
struct StepSummary {
  double max_speed = 0;  // max over cells of Physics::speed [length/time]
  double checksum = 0;   // sum of all components of all cells
};

// The fewest cells a segment of a grid stepped by several threads holds: a
// step of 2 10^4 cells takes about 0.2 ms, a stage of a thread team about 10 us.
inline constexpr std::size_t kSegmentCells = 4096;

// The threads that step a grid of `cells` cells: at most `threads`, each with
// at least kSegmentCells cells (1 for a smaller grid).
inline std::size_t grid_threads(std::size_t cells, std::size_t threads) {
  return std::max<std::size_t>(1, std::min(threads, cells / kSegmentCells));
}

template <FiniteVolumePhysics PhysicsT>
class FiniteVolumeGrid {
 public:
  using Physics = PhysicsT;
  using State = typename Physics::State;
  static constexpr std::size_t ghosts = 2;
  static constexpr std::size_t components = Physics::components;

  // cells: initial cell averages (at least 2); dx: cell width [length];
  // threads: the segments, each stepped by a thread of its own (grid_threads).
  FiniteVolumeGrid(const std::vector<State>& cells, double dx, Boundary boundary, std::size_t threads = 1)
      : n_(cells.size()), dx_(dx), boundary_(boundary) {
    assert(n_ >= 2 && dx > 0);
    const std::size_t segments = grid_threads(n_, threads);
    for (std::size_t k = 0; k <= segments; ++k) begin_.push_back(n_ * k / segments);
    for (std::size_t k = 0; k < segments; ++k) {
      segments_.emplace_back(begin_[k + 1] - begin_[k] + 2 * ghosts);
      std::copy(cells.begin() + static_cast<std::ptrdiff_t>(begin_[k]),
                cells.begin() + static_cast<std::ptrdiff_t>(begin_[k + 1]), segments_[k].begin() + ghosts);
    }
    if (segments > 1) team_ = std::make_unique<ThreadTeam>(segments);
  }

  std::size_t size() const { return n_; }
  double dx() const { return dx_; }
  const State& cell(std::size_t i) const {
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(begin_.begin(), begin_.end(), i) - begin_.begin()) - 1;
    return segments_[k][i - begin_[k] + ghosts];
  }

  // Max speed and checksum of the current cells.
  StepSummary summary() const {
    StepSummary s;
    for (std::size_t i = 0; i < n_; ++i) account(s, cell(i));
    return s;
  }

  // Index of the first cell with a non-finite component, or size() if none.
  std::size_t first_non_finite() const {
    for (std::size_t i = 0; i < n_; ++i)
      for (double c : cell(i))
        if (!std::isfinite(c)) return i;
    return n_;
  }

  // First-order Godunov step.
  StepSummary step_godunov(double dt) {
    const double lambda = dt / dx_;
    return each_segment([lambda](State* u, std::size_t n) { return sweep_godunov(u, n, lambda); });
  }

  // Second-order MUSCL-Hancock step with slope limiter Lim (limiters.hpp).
  template <class Lim>
  StepSummary step_muscl_hancock(double dt) {
    const double lambda = dt / dx_;
    return each_segment([lambda](State* u, std::size_t n) { return sweep_muscl_hancock<Lim>(u, n, lambda); });
  }

 private:
  static void account(StepSummary& s, const State& u) {
    s.max_speed = std::max(s.max_speed, static_cast<double>(Physics::speed(u)));
    double cell_sum = 0;  // summed apart: one add per cell on the running sum's chain
    for (double c : u) cell_sum += c;
    s.checksum += cell_sum;
  }

  // The ghost cells of every segment: its neighbours' edge cells, or at the
  // grid's ends the boundary rule (periodic: the other end's; outflow: copies
  // of the edge cell).
  void fill_ghosts() {
    const std::size_t last = segments_.size() - 1;
    for (std::size_t k = 0; k <= last; ++k) {
      State* u = segment(k);
      const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(length(k));
      const bool periodic = boundary_ == Boundary::periodic;
      const std::size_t left = k > 0 ? k - 1 : last, right = k < last ? k + 1 : 0;
      const std::ptrdiff_t n_left = static_cast<std::ptrdiff_t>(length(left));
      for (std::ptrdiff_t g = 1; g <= static_cast<std::ptrdiff_t>(ghosts); ++g) {
        u[-g] = k > 0 || periodic ? segment(left)[n_left - g] : u[0];
        u[n - 1 + g] = k < last || periodic ? segment(right)[g - 1] : u[n - 1];
      }
    }
  }

  // sweep(cells, count) on every segment, its ghosts filled first; their
  // summaries combined (the largest speed, the checksums summed).
  template <class Sweep>
  StepSummary each_segment(const Sweep& sweep) {
    fill_ghosts();
    if (!team_) return sweep(segment(0), length(0));
    parts_.resize(segments_.size());
    team_->run([&](std::size_t k) { parts_[k] = sweep(segment(k), length(k)); });
    StepSummary s;
    for (const StepSummary& p : parts_)
      s.max_speed = std::max(s.max_speed, p.max_speed), s.checksum += p.checksum;
    return s;
  }

  State* segment(std::size_t k) { return segments_[k].data() + ghosts; }
  std::size_t length(std::size_t k) const { return begin_[k + 1] - begin_[k]; }

  // U_i <- U_i - lambda (F_{i+1/2} - F_{i-1/2}) for cells u[0 .. n-1] in place
  // (u[-2], u[-1], u[n], u[n+1] the ghosts), first order: the flux at the right
  // face of cell i is computed from the old U_i and U_{i+1} before U_i is
  // overwritten.
  static StepSummary sweep_godunov(State* u, std::size_t n, double lambda) {
    State left_flux = Physics::riemann_flux(u[-1], u[0]);
    StepSummary s;
    for (std::size_t i = 0; i < n; ++i) {
      const State right_flux = Physics::riemann_flux(u[i], u[i + 1]);
      for (std::size_t k = 0; k < components; ++k) u[i][k] -= lambda * (right_flux[k] - left_flux[k]);
      account(s, u[i]);
      left_flux = right_flux;
    }
    return s;
  }

  // The same, second order (MUSCL-Hancock), in one pass: the faces of cell
  // i+1 are built from the old U_i, U_{i+1}, U_{i+2} before U_i is overwritten.
  template <class Lim>
  static StepSummary sweep_muscl_hancock(State* u, std::size_t n, double lambda) {
    Faces here = evolved_faces<Lim>(u, 0.5 * lambda);
    State left_flux = Physics::riemann_flux(evolved_faces<Lim>(u - 1, 0.5 * lambda).plus, here.minus);
    StepSummary s;
    for (std::size_t i = 0; i < n; ++i) {
      const Faces next = evolved_faces<Lim>(u + i + 1, 0.5 * lambda);
      const State right_flux = Physics::riemann_flux(here.plus, next.minus);
      for (std::size_t k = 0; k < components; ++k) u[i][k] -= lambda * (right_flux[k] - left_flux[k]);
      account(s, u[i]);
      left_flux = right_flux;
      here = next;
    }
    return s;
  }

  struct Faces {
    State minus, plus;  // values at the left and right face of a cell
  };

  // Limited reconstruction U_i -/+ dU_i / 2 of the cell at c (reads c[-1], c[0],
  // c[1]), each face moved half a step by the cell's own flux difference:
  // U_face -= (dt / 2dx) (F(U+) - F(U-)).
  template <class Lim>
  static Faces evolved_faces(const State* c, double half_lambda) {
    Faces f;
    for (std::size_t k = 0; k < components; ++k) {
      const double half_slope = 0.5 * Lim::slope(c[0][k] - c[-1][k], c[1][k] - c[0][k]);
      f.minus[k] = c[0][k] - half_slope;
      f.plus[k] = c[0][k] + half_slope;
    }
    const State f_minus = Physics::flux(f.minus), f_plus = Physics::flux(f.plus);
    for (std::size_t k = 0; k < components; ++k) {
      const double change = half_lambda * (f_plus[k] - f_minus[k]);
      f.minus[k] -= change;
      f.plus[k] -= change;
    }
    return f;
  }

  std::size_t n_;
  double dx_;
  Boundary boundary_;
  std::vector<std::size_t> begin_;  // segment k holds cells begin_[k] .. begin_[k + 1] - 1
  std::vector<std::vector<State>>
      segments_;                      // each with its ghosts: segments_[k][ghosts + j] is cell begin_[k] + j
  std::unique_ptr<ThreadTeam> team_;  // one member per segment (none for one segment)
  std::vector<StepSummary> parts_;    // each segment's summary of a step
};

// ---- The time loop and the input rules shared by the finite-volume solvers ----

// Largest Courant number dt max|speed| / dx each scheme is stable for (see above).
inline constexpr double kGodunovCflMax = 1.0;
// MUSCL-Hancock keeps total variation bounded only while the limited slope stays
// within the CFL-dependent TVD region (Toro, Riemann Solvers, 3rd ed., §14.4):
// minmod never leaves it up to CFL 1; van Leer and MC, whose slopes reach twice
// the one-sided difference, leave it earlier. The bounds below are where the
// total-variation scan of `shockgas bench` (stability_cfl_limits.csv, tested in
// BenchStability.*) first sees the variation grow: 0.9 and 0.85.
inline constexpr double kMusclHancockCflMax = 1.0;  // minmod
inline constexpr double kMusclHancockVanLeerCflMax = 0.9;
inline constexpr double kMusclHancockMcCflMax = 0.85;

// Checks continuum.cells (>= 8: a periodic stencil of 5 cells plus room for one
// wave to be resolved), continuum.cfl (in (0, cfl_max] unless allow_unstable),
// and t_end (finite, >= 0). Throws InputError naming the key.
void check_finite_volume_input(const ContinuumParams& p, double t_end, double cfl_max,
                               const std::string& scheme);
// Throws InputError naming initial.v0 / initial.rho0 if a cell average of the
// initial data is not finite or a density is negative.
void check_initial_averages(const CellAverages& a, double length);

// Throws RunError: "<solver>: non-finite <component> = <value> in cell i (x = ...) at t = ...".
[[noreturn]] void throw_non_finite(const std::string& solver, double t, std::size_t step, std::size_t cell,
                                   double x, const std::string& component, double value);
// Throws RunError when the time step no longer advances t.
[[noreturn]] void throw_stalled(const std::string& solver, double t, double dt);

struct TimeLoop {
  double t_end = 0;           // final time [time], reached exactly
  double cfl = 0.5;           // Courant number: dt = cfl dx / max|speed|
  std::string solver;         // name for errors (the registered name)
  ProgressCallback progress;  // called about every 1% of t_end, and every kProgressSteps steps
};

// Steps between two progress reports at most: the reports are where a solve
// stops on an interrupt or at the run's wall limit, and 1% of a long t_end can
// be more steps than a run will ever take.
inline constexpr std::size_t kProgressSteps = 1024;

// Advances grid to loop.t_end with step(dt) -> StepSummary; returns the number of
// steps. The last step is shortened so that t lands on t_end exactly. A
// non-finite cell after any step throws RunError (solver, time, cell).
template <class Grid, class StepFn>
std::size_t advance(Grid& grid, const TimeLoop& loop, StepFn&& step) {
  StepSummary s = grid.summary();
  double t = 0;
  std::size_t steps = 0;
  double next_report = 0.01;
  while (t < loop.t_end) {
    const double remaining = loop.t_end - t;
    double dt = s.max_speed > 0 ? loop.cfl * grid.dx() / s.max_speed : remaining;
    const bool last = dt >= remaining;
    if (last) dt = remaining;
    if (!(t + dt > t)) throw_stalled(loop.solver, t, dt);
    s = step(dt);
    ++steps;
    t = last ? loop.t_end : t + dt;
    if (!std::isfinite(s.checksum)) {  // some cell is not finite (or the sum overflowed)
      const std::size_t i = grid.first_non_finite();
      if (i < grid.size()) {
        const auto& u = grid.cell(i);
        std::size_t k = 0;
        while (k + 1 < u.size() && std::isfinite(u[k])) ++k;
        throw_non_finite(loop.solver, t, steps, i, (static_cast<double>(i) + 0.5) * grid.dx(),
                         Grid::Physics::component_names[k], u[k]);
      }
    }
    if (loop.progress && (t >= next_report * loop.t_end || steps % kProgressSteps == 0)) {
      loop.progress(t / loop.t_end, t, 0);
      next_report = std::floor(100 * t / loop.t_end + 1) / 100;
    }
  }
  return steps;
}

}  // namespace shockgas::continuum
