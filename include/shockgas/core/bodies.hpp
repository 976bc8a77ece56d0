#pragma once
// A one-dimensional state of point masses: what every model starts from and
// what the particle engine and the exact sticky solver return.
#include <cstddef>
#include <vector>

namespace shockgas {

struct Bodies {
  std::vector<double> x;  // positions, sorted ascending [length]
  std::vector<double> v;  // velocities [length / time]
  std::vector<double> m;  // masses [mass; a particle has m = 1]

  std::size_t size() const { return x.size(); }
  void reserve(std::size_t n) {
    x.reserve(n);
    v.reserve(n);
    m.reserve(n);
  }
  void push_back(double xi, double vi, double mi) {
    x.push_back(xi);
    v.push_back(vi);
    m.push_back(mi);
  }
};

// Total mass, momentum and kinetic energy (sum m v^2 / 2).
double total_mass(const Bodies& b);
double total_momentum(const Bodies& b);
double kinetic_energy(const Bodies& b);
// Mass-weighted temperature T = <v^2> - <v>^2.
double temperature(const Bodies& b);

}  // namespace shockgas
