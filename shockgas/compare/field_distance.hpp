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

}  // namespace shockgas::compare
