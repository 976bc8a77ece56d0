#pragma once
// A one-dimensional state of point masses: what every model starts from and
// what the particle engine and the exact sticky solver return.
#include <cstddef>
#include <span>
#include <string>
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

// Bodies held elsewhere, read in place: what a function that only reads the
// bodies takes (a Bodies converts to it; so do a caller's own arrays).
struct BodiesView {
  std::span<const double> x, v, m;  // as in Bodies

  BodiesView(const Bodies& b) : x(b.x), v(b.v), m(b.m) {}  // NOLINT: implicit by design
  BodiesView(std::span<const double> x_, std::span<const double> v_, std::span<const double> m_)
      : x(x_), v(v_), m(m_) {}
  std::size_t size() const { return x.size(); }
};

// InputError naming body i by its index if it lacks a finite position, a
// finite velocity or a finite mass > 0: KEY.x[i], KEY.v[i], KEY.m[i] (key:
// "initial.bodies", "compare.bodies"); require_finite_bodies: the first such body.
void require_finite_body(BodiesView b, std::size_t i, const std::string& key);
void require_finite_bodies(BodiesView b, const std::string& key);

// Total mass, momentum and kinetic energy (sum m v^2 / 2).
double total_mass(const Bodies& b);
double total_momentum(const Bodies& b);
double kinetic_energy(const Bodies& b);
// Mass-weighted temperature T = <v^2> - <v>^2.
double temperature(const Bodies& b);

// The same temperature in one pass, as bodies go by in chunks (a run that
// draws its bodies once): in blocks of kBlock bodies, whatever the chunks,
// each summed in two passes about its own mean (M_b, mean_b, C_b = sum m (v -
// mean_b)^2) and combined in order by Chan, Golub & LeVeque's update
// (C += C_b + d^2 M M_b / (M + M_b), d = mean_b - mean). Equal to temperature()
// to rounding (about N eps relative, no cancellation), not bit for bit; the
// same bits for the same bodies in the same order however they are chunked.
// Their kinetic energy too, summed in their order as kinetic_energy() sums
// it (the same bits), in the blocks' first pass.
class TemperatureSums {
 public:
  static constexpr std::size_t kBlock = 4096;
  void add(const double* v, const double* m, std::size_t count);
  double temperature() const;
  double kinetic_energy() const;

 private:
  struct FirstPass {
    double mass, mean;
  };
  FirstPass first_pass(const double* v, const double* m, std::size_t n);
  static double second_pass(const double* v, const double* m, std::size_t n, double mean);
  void combine(FirstPass block, double squares);
  // Adds the sums of `blocks` whole blocks (>= 1) at v, m.
  void take_blocks(const double* v, const double* m, std::size_t blocks);
  std::vector<double> v_, m_;  // the block being filled
  double mass_ = 0, mean_ = 0, squares_ = 0, energy_ = 0;
};

}  // namespace shockgas
