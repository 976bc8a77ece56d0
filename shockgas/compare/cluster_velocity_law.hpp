#pragma once
// The exact law of the clusters' velocities (the shocks of Burgers turbulence,
// the sticky gas at r = 0) from white-noise initial velocity, weighted by mass
// (the paper's Fig. 4 for r = 0) or by number, and the number of shocks.
//
// Scaled units as in eulerian_velocity_law.hpp: lengths and masses in units of
// a = (4 D t^2)^(1/3) (uniform initial density 1), velocities in units of a/t,
// so that in shockgas units z = (v - U) t^(1/3) = (4 D)^(1/3) u. There, with W a
// two-sided Brownian motion, the Eulerian point xi has Lagrangian preimage
// argmin_s F(s), F(s) = (xi - s)^2 + W(s). A shock sits at xi where F has two
// minimisers s_L < s_R; it holds the mass mu = s_R - s_L and, since
// W(s_R) - W(s_L) = mu (2 xi - s_L - s_R), moves at its mean initial velocity
// u = xi - (s_L + s_R)/2. With alpha = xi - s_L, beta = s_R - xi (alpha + beta = mu,
// u = (alpha - beta)/2) the shocks form a stationary point process with
// intensity per unit length
//
//     n(alpha, beta) = 2 (alpha + beta) g(alpha) g(beta) K(alpha + beta),
//     K(mu) = sum_k exp(2^(1/3) a_k mu)                    (a_k the zeros of Ai),
//
// g Groeneboom's function (chernoff.hpp). Derivation: (i) as xi grows by dxi, F
// changes by -2 s dxi (up to a constant), so the minimiser jumps from s_L to s_R
// within dxi iff F(s_R) - F(s_L) is in [0, 2 mu dxi): the factor mu. (ii) Given
// the two touchings at the level m, the path falls into three independent
// pieces (Markov property). X = W + (s - xi)^2 - m >= 0 is Brownian motion with
// drift 2(s - xi), zero at s_L and s_R. Right of s_R it stays positive, which
// gives the entrance factor h(beta) = d/dx P_x(X > 0 on (s_R, inf)) at x = 0; left
// of s_L, by the reflection s -> 2 xi - s, h(alpha). Between them X makes an
// excursion: by Girsanov its density is exp(-(2/3)(alpha^3 + beta^3)) times that
// of Brownian motion killed at 0 and at rate 2x, whose kernel has the
// eigenfunctions Ai(4^(1/3) x + a_k), eigenvalues 2^(1/3) a_k and norms
// 4^(-1/3) Ai'(a_k)^2, so d/dx d/dy of it at x = y = 0 is 4 K(mu). Groeneboom's
// g is h(s) exp(-(2/3) s^3) (one touching gives Chernoff's f = h(z) h(-z) / 2 =
// g(z) g(-z) / 2, and h(s) -> 4 s, g(s) -> 4 s exp(-(2/3) s^3) as s -> inf), so the
// three pieces make g(alpha) g(beta) K(alpha + beta).
// (iii) The constant 2: the particle at s = 0 lies in the shock at xi iff
// s_L < 0 < s_R, and its cluster is right of xi iff q*(xi) < 0, so
//     int_{alpha > xi} int_{beta > -xi} n(alpha, beta) = f(xi)  (Chernoff's density)
// for every xi; this switching identity holds with the constant 2 (and only
// with it) to 1e-14 (tests/compare/test_cluster_velocity_law.cpp), and
// integrating it over xi gives mass conservation, int int (alpha + beta) n = 1.
//
// Hence the velocity of the cluster holding a randomly picked particle
// (mass-weighted) and of a randomly picked cluster (number-weighted):
//     P_mass(u) = 2 int_0^inf mu^2 K(mu) g(mu/2 + u) g(mu/2 - u) dmu,
//     P_number(u) = (2 / n_s) int_0^inf mu K(mu) g(mu/2 + u) g(mu/2 - u) dmu,
//     n_s = 2 int_0^inf mu K(mu) (g * g)(mu) dmu = 2.1085 shocks per unit length a.
// K(mu) ~ (2^(1/3) mu)^(-3/2) / (2 sqrt(pi)) - 1/4 + ... for mu -> 0 (the Brownian
// excursion; the Hankel transform of Ai'/Ai ~ -sqrt(w) - 1/(4w) + ...), so small
// shocks are many (P(mu) ~ mu^(-1/2)) but hold little mass. For |u| -> inf the
// mass integral is dominated by mu ~ u^(-2) and P_mass(u) ~ f(u) / (sqrt(2) |u|^3):
// the same exp(-(2/3)|u|^3) tail as the Eulerian law, with a power fewer of |u|.
// E_mass u^2 = 0.17571 (Eulerian: 0.26356): the r = 0 gas's temperature is
// T t^(2/3) -> (4 D)^(2/3) 0.17571, 0.2129 for uniform velocities on [-1, 1].
// (Frachebourg & Martin, J. Fluid Mech. 417 (2000) 323, derive the shock
// statistics of this problem; the formulas here were derived independently in
// this form and are checked by the switching identity and by the exact hull.)
#include <cstddef>
#include <span>
#include <vector>

#include "shockgas/core/sticky_hull.hpp"

namespace shockgas::compare {

// K(s / 2^(1/3)) = sum_k exp(a_k s), s > 0: the direct sum over the zeros for
// s >= 0.3, else its small-s expansion to s^(21/2) (error < 1e-12 relative).
// Throws InputError unless s > 0.
double airy_zero_exponential_sum(double s);

// The zeros a_1 > a_2 > ... > a_1000 of Ai that sum takes: computed
// (airy_ai_zero, airy.hpp), and the build's (stored_law_tables.cpp).
std::vector<double> compute_airy_zeros();
const std::vector<double>& airy_zeros();

// The law in scaled units (u), built once: its density by Gauss-Legendre
// quadrature in sqrt(mu) (208 nodes; g from chernoff_log_g_table), its CDF from a
// table of that density's integrals on [-5, 5].
class ClusterVelocityLaw {
 public:
  // What the law is built of: the quadrature in mu and the CDF table.
  struct Nodes {
    std::vector<double> mu, weight;  // nodes and weights (K folded in)
    std::vector<double> cumulative;  // P_mass integrated up to each grid point of [-5, 5]
    double shocks = 0;               // n_s [1/a]
  };
  // Computes the law (about 0.1 s, from chernoff_log_g_table and airy_zeros).
  ClusterVelocityLaw();
  // A law computed before.
  explicit ClusterVelocityLaw(Nodes nodes);
  const Nodes& nodes() const { return n_; }
  double mass_density(double u) const;                // P_mass(u)
  double number_density(double u) const;              // P_number(u)
  double shock_density() const { return n_.shocks; }  // n_s [1/a]
  double mass_cdf(double u) const;
  double mass_quantile(double p) const;  // throws InputError unless 0 < p < 1
  // int_a^b P_mass (either order), by 8-point Gauss-Legendre on panels <= 0.05.
  double mass_integral(double a, double b) const;

 private:
  double moment_sum(double u, int power) const;  // int mu^power K(mu) g(mu/2+u) g(mu/2-u) dmu
  Nodes n_;
};

// One law shared by the functions below: the build's (stored_law_tables.cpp).
const ClusterVelocityLaw& cluster_velocity_law();

// E_mass u^2 of the law, by quadrature of its density (0.1757064): computed,
// and the build's (stored_law_tables.cpp).
double compute_cluster_law_second_moment(const ClusterVelocityLaw& law);
double cluster_law_second_moment();

// In shockgas units z = (v - U) t^(1/3) = (4 D)^(1/3) u (D > 0, as in
// eulerian_velocity_law.hpp): the mass-weighted density, CDF and quantile, and
// bin means (F(b) - F(a)) / (b - a) for histograms.
double cluster_velocity_density(double z, double D);
double cluster_velocity_cdf(double z, double D);
double cluster_velocity_quantile(double p, double D);
std::vector<double> cluster_law_on_bins(std::span<const double> z_edges, double D);

// Samples of the mass-weighted law from an exact sticky state: for every
// `stride`-th initial body (0, stride, ...) of `bodies`, z = (v_c - U) t^(1/3) of
// the cluster holding it (clusters as from sticky_clusters_ring; U the mean
// initial velocity). Bodies further apart than the largest clusters (a few a)
// give independent samples. Throws InputError unless t > 0, stride >= 1 and the
// clusters cover the bodies.
std::vector<double> cluster_velocity_samples(const std::vector<StickyCluster>& clusters, std::size_t bodies,
                                             double mean_velocity, double t, std::size_t stride);

}  // namespace shockgas::compare
