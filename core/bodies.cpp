#include "shockgas/core/bodies.hpp"

namespace shockgas {

double total_mass(const Bodies& b) {
  double s = 0;
  for (double mi : b.m) s += mi;
  return s;
}

double total_momentum(const Bodies& b) {
  double s = 0;
  for (std::size_t i = 0; i < b.size(); ++i) s += b.m[i] * b.v[i];
  return s;
}

double kinetic_energy(const Bodies& b) {
  double s = 0;
  for (std::size_t i = 0; i < b.size(); ++i) s += 0.5 * b.m[i] * b.v[i] * b.v[i];
  return s;
}

double temperature(const Bodies& b) {
  const double m = total_mass(b);
  if (m <= 0) return 0;
  const double mean = total_momentum(b) / m;
  double s = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double dv = b.v[i] - mean;
    s += b.m[i] * dv * dv;
  }
  return s / m;
}

}  // namespace shockgas
