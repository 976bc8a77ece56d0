#pragma once
// The L1 distance between a field and a reference on the same uniform grid,
// normalised so that it reads the same at any domain length and any amplitude:
//
//     per_length = (1/L) int |a - b| dx           the mean distance [unit of the field]
//     relative   = int |a - b| dx / int |b - c| dx  against the size of the reference [1]
//
// with cell averages a_i, b_i (b the reference) and int = sum dx. The scale c
// is the reference's mean for a velocity (its variation about the mean: the
// number does not change under a Galilean shift v -> v + U) and 0 for a
// density (int rho dx is the mass: relative = the fraction of the mass misplaced,
// at most 2 for two densities of equal mass). A reference without any variation
// gives relative = NaN.
#include <vector>

namespace shockgas::compare {

struct L1Distance {
  double per_length = 0;  // (1/L) int |a - b| dx [unit of the field]
  double relative = 0;    // int |a - b| dx / int |b - c| dx [1]
};

enum class L1Scale {
  about_mean,  // c = the reference's mean (velocities)
  absolute,    // c = 0 (densities)
};

// Throws InputError unless a and b have the same, nonzero number of cells.
L1Distance l1_distance(const std::vector<double>& a, const std::vector<double>& reference, L1Scale scale);

// Where the mass is: the Wasserstein-1 distance of two densities on a ring of
// length L, by their cumulative mass distributions M(x) = int_0^x rho / int_0^L rho,
//
//     W1 / L = min_c (1/L) int_0^L |M_a(x) - M_b(x) - c| dx,
//
// the mean distance the mass must move to turn one density into the other, as a
// fraction of L (on a circle the best c is the median of M_a - M_b: Werman,
// Peleg & Rosenfeld, CVGIP 32, 328 (1985); Rabin, Delon & Gousseau, J. Math.
// Imaging Vis. 41, 147 (2011)). Unlike the L1 distance of the densities it is
// small when a delta-shock sits in the right place: a mass fraction f moved by
// one cell of n costs f / n. Each cell's mass sits at its centre, so M steps
// there and the integral is the sum over the gaps between neighbouring centres
// of |M_a - M_b - c| dx: the exact W1 of those point masses.
// Throws InputError unless both have the same, nonzero number of cells and a
// positive mass.
double mass_distance(const std::vector<double>& rho, const std::vector<double>& reference);

}  // namespace shockgas::compare
