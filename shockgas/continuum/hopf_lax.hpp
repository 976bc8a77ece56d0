#pragma once
// The exact inviscid limit of Burgers + continuity (Hopf-Lax, Legendre transform).
//
//     v_t + v v_x = 0,  rho_t + (rho v)_x = 0  (entropy / adhesion solution)
//     Psi(x, t) = min_q [ (x - q)^2 / (2t) + Psi0(q) ],   Psi0' = v0,
//     v(x, t) = dPsi/dx = (x - q*(x)) / t,
//
// with q*(x) the minimiser (the Lagrangian coordinate of x). Minimising over q
// is a Legendre transform: q*(x) is where the lower convex hull of
// g(q) = q^2/2 + t Psi0(q) has slope x. Shocks are the hull's long edges; a shock
// holds the mass M0(q_R) - M0(q_L) of the Lagrangian interval it swallowed,
// M0' = rho0 (Hopf 1950; Lax 1957; E, Rykov & Sinai 1996).
//
// Exact cell averages need no quadrature of the solution:
//     <v>_[a,b] = (Psi(b) - Psi(a)) / (b - a),
//     <rho>_[a,b] = (M0(q*(b)) - M0(q*(a))) / (b - a).
//
// Periodic domain [0, L). A non-zero mean velocity U = <v0> is removed by a
// Galilean shift (Psi0 is then periodic): v(x, t) = U + w(x - U t, t).
//
// The hull is the sticky-particle hull of shockgas/core/sticky_hull.hpp: sampling Psi0 at
// nodes q_j = j L / n and treating each sample interval as a body of "mass" L/n at
// its midpoint with the interval's mean velocity gives cumulative points that are
// exactly (q_j, g(q_j)); one period of them goes through sticky_clusters_ring.
// For point-mass data the shocks are the sticky gas's clusters and the ramps
// between them have slope 1/t (hopf_lax_point_masses).
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/initial_condition.hpp"

namespace shockgas::continuum {

// Resolution of the sampled Legendre transform. The samples only locate each
// minimiser to within one sample; it is then refined on the exact v0 to rounding.
struct HopfLaxOptions {
  std::size_t samples_per_cell = 4;  // samples of Psi0 per output cell [1], >= 1
  std::size_t min_samples = 2048;    // lower bound on samples per period [1], >= 16
  std::size_t multiple_of = 0;       // if > 0, samples per period rounded up to a multiple of
                                     // it [1]: for data piecewise on that many equal cells
                                     // (cell averages as v0), so that every kink is a node
};

// The exact solution at one time t >= 0 for pointwise data (f.v0, optional
// f.rho0 = 1 if absent) on the periodic domain [0, f.length). Building it costs
// O(n) for n samples per period (quadrature of v0 and rho0 plus one hull);
// each evaluation costs O(log n) plus a few dozen evaluations of v0.
// v0 and rho0 are only evaluated on [0, f.length). The const members update
// work counters (stats()), so one object is not for concurrent use.
class HopfLaxSolution {
 public:
  // samples: samples of Psi0 per period (>= 16). Throws InputError for bad
  // input, including v0 or rho0 non-finite (or rho0 < 0) at a sample.
  HopfLaxSolution(const InitialField& f, double t, std::size_t samples);

  double time() const { return t_; }
  double length() const { return L_; }
  double mean_velocity() const { return U_; }  // U = (1/L) int_0^L v0 [length/time]
  double total_mass() const { return mass_; }  // int_0^L rho0 [mass]
  std::size_t samples() const { return n_; }

  // Everything known at one point x (lab frame, any real x).
  struct Point {
    double q = 0;     // Lagrangian coordinate q*(x), unwrapped: q*(x + L) = q*(x) + L
    double psi = 0;   // Psi(x, t) = min_q [(x - q)^2/(2t) + Psi0(q)], Psi0(q) = int_0^q v0
    double v = 0;     // v(x, t) = dPsi/dx (at a shock: the value of one of its sides)
    double mass = 0;  // cumulative mass M(x, t) = M0(q*(x)), M0(q) = int_0^q rho0
  };
  Point at(double x) const { return locate(x, true); }
  double lagrangian(double x) const { return at(x).q; }
  double potential(double x) const { return at(x).psi; }
  double velocity(double x) const { return at(x).v; }
  double mass_left_of(double x) const { return at(x).mass; }

  // The shocks with x in [0, L), sorted by x. A shock whose Lagrangian interval
  // is narrower than one sample (t just after it forms) is not listed.
  std::vector<Shock> shocks() const;

  // Exact cell averages on `cells` cells of [0, L): potential and Lagrangian
  // mass differences at the cell edges over dx.
  CellAverages cell_averages(std::size_t cells) const;

  // Counters: "samples", "hull_clusters", "v0_evaluations", "unbracketed"
  // (minimisers that could not be bracketed between samples and were taken at
  // the best sample instead; non-zero means v0 varies below the sample spacing).
  std::map<std::string, double> stats() const;

 private:
  struct Minimum {
    double q = 0;    // minimiser, moving frame, unwrapped
    double psi = 0;  // Psi_w at the evaluation point (moving frame, periodic)
  };
  struct Frame {
    double k;  // periods
    double y;  // moving-frame position in [0, L)
  };
  Frame moving_frame(double x) const;
  Point locate(double x, bool with_velocity) const;
  double moving_velocity(double y, double q) const;
  Minimum minimum(double y) const;  // y: moving-frame position in [0, L)
  Minimum refine(double y, long node) const;
  double root_near(double y, long node, bool& bracketed) const;
  double wrap(double q) const;
  double v0(double q) const;
  double w0(double q) const { return v0(q) - U_; }
  double rho0(double q) const;
  double psi0(double q) const;  // Psi0_w(q) = int_0^q (v0 - U), any q
  double m0(double q) const;    // M0(q), any q
  double node_q(long node) const { return static_cast<double>(node) * h_; }
  long node_below(double q) const;
  std::size_t node_index(long node) const;
  long node_period(long node) const;
  void build_tables();
  void build_hull();

  std::function<double(double)> v0_, rho0_;
  double t_ = 0, L_ = 1, h_ = 1, U_ = 0, mass_ = 0;
  std::size_t n_ = 0;
  std::vector<double> psi_;       // Psi0_w at nodes 0..n-1 (moving frame, periodic)
  std::vector<double> mcum_;      // M0 at nodes 0..n-1
  std::size_t period_edges_ = 0;  // hull edges (clusters) per period
  std::vector<double> hull_x_;    // hull edge slopes (cluster positions) over 3 periods, ascending
  std::vector<long> hull_start_;  // first node of each edge; edge c spans nodes [start_c, start_{c+1}]
  mutable std::size_t evaluations_ = 0, unbracketed_ = 0;
};

// The exact solution on `cells` cells of [0, f.length) at time t: cell averages
// of v and rho, and the shocks (has_shocks = true). Pointwise data go through
// HopfLaxSolution, point masses (f.bodies) through hopf_lax_point_masses.
ContinuumResult solve_hopf_lax(const InitialField& f, std::size_t cells, double t,
                               const HopfLaxOptions& options = {});

// Only the cell averages of solve_hopf_lax: the reference for the order tests
// of the finite-volume schemes.
CellAverages exact_cell_averages(const InitialField& f, std::size_t cells, double t,
                                 const HopfLaxOptions& options = {});

// The exact adhesion field of point masses f.bodies on the ring [0, f.length)
// at time t (the fields and shocks of solve_hopf_lax; solver, t, x left unset).
// Body i is the mass of its Lagrangian cell, the interval between the midpoints
// to its ring neighbours; a cluster of the sticky gas (sticky_clusters_ring:
// position, velocity = momentum / mass and mass unchanged) owns the union
// [q_L, q_R] of its bodies' cells. Between clusters lies vacuum whose
// Lagrangian preimage is the one boundary q_b between them, so there
//     v(x, t) = (x - q_b) / t        (slope exactly 1/t; docs/design.md §1),
// and at a cluster v jumps by (q_L - q_R) / t. Cell averages: <v> integrates the
// ramps exactly; rho = the clusters' masses / dx in the cell [i dx, (i+1) dx)
// holding them (one exactly on an edge: the cell on its right), 0 in vacuum.
// Shocks: the clusters of two or more bodies, jump (q_L - q_R) / t, velocity
// the cluster's. At t = 0 the fields are the deposit cell_averages(f, cells).
// O(N + cells). For lattice bodies with unit masses and data v0 = u_i on the
// bodies' cells this is the Hopf-Lax field of that v0 once no body's cell is
// split between a shock and a ramp.
ContinuumResult hopf_lax_point_masses(const InitialField& f, std::size_t cells, double t);

// Samples per period that solve_hopf_lax uses for `cells` cells.
std::size_t hopf_lax_samples(std::size_t cells, const HopfLaxOptions& options = {});

// Its registration (registry.hpp): the exact reference of every comparison.
SolverInfo hopf_lax_solver();

}  // namespace shockgas::continuum
