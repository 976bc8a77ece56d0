#pragma once
// The engine's state at a time as a StateReader (private to particles/): the
// live bodies sorted by x, ring positions wrapped into [0, L), in chunks, read
// straight from the engine's arrays.
//
// In chain order from body 0 the unrolled positions never decrease and span at
// most L, so the wrapped ones rise to the seam (where they drop by about L) and
// rise again: the order by x starts at the seam. A first pass finds it; rounding
// at the wrap can leave equal neighbours misordered, and then (rarely) the state
// is sorted through a copy, as the recorder's final state is.
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

#include "event_engine.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles::detail {

template <bool Linked>
class EngineState final : public StateReader {
 public:
  EngineState(const EventEngine<Linked>& e, double t) : e_(e), t_(t) { find_seam(); }

  std::size_t size() const override { return e_.alive(); }

  void read(const Chunk& chunk) const override {
    if (!sorted_) return read_sorted_copy(chunk);
    Buffer buffer;
    // Chain positions seam .. end, then 0 .. seam - 1.
    for (int part = 0; part < 2; ++part) {
      std::size_t k = 0;
      e_.for_each_body(t_, [&](std::size_t, double x, double v, double m) {
        const bool first_part = k++ >= seam_;
        if (first_part == (part == 0)) buffer.push(wrap(x), v, m, chunk);
      });
    }
    buffer.flush(chunk);
  }

 private:
  static constexpr std::size_t capacity = 1024;
  struct Buffer {
    std::array<double, capacity> x, v, m;
    std::size_t n = 0;
    void push(double xi, double vi, double mi, const Chunk& chunk) {
      x[n] = xi, v[n] = vi, m[n] = mi;
      if (++n == capacity) flush(chunk);
    }
    void flush(const Chunk& chunk) {
      if (n > 0) chunk(x.data(), v.data(), m.data(), n);
      n = 0;
    }
  };

  // A ring position wrapped into [0, L): x - L floor(x / L), where a result that
  // rounding leaves at L (or below 0) becomes 0.
  double wrap(double x) const {
    if (!e_.ring()) return x;
    const double L = e_.length();
    const double w = x - L * std::floor(x / L);
    return w >= L || w < 0 ? 0.0 : w;
  }

  // The seam (the first drop of the wrapped positions), and whether the order
  // starting there is sorted.
  void find_seam() {
    std::size_t k = 0, drops = 0;
    double first = 0, last = 0;
    e_.for_each_body(t_, [&](std::size_t, double x, double, double) {
      const double w = wrap(x);
      if (k == 0) first = w;
      if (k > 0 && w < last && drops++ == 0) seam_ = k;
      last = w;
      ++k;
    });
    sorted_ = drops == 0 || (drops == 1 && last <= first);
  }

  // The state sorted through a copy: a stable sort of the order from the seam.
  void read_sorted_copy(const Chunk& chunk) const {
    std::vector<double> x, v, m;
    e_.for_each_body(t_, [&](std::size_t, double xi, double vi, double mi) {
      x.push_back(wrap(xi)), v.push_back(vi), m.push_back(mi);
    });
    for (std::vector<double>* a : {&x, &v, &m})
      std::rotate(a->begin(), a->begin() + static_cast<std::ptrdiff_t>(seam_), a->end());
    std::vector<std::size_t> order(x.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return x[i] < x[j]; });
    Buffer buffer;
    for (std::size_t i : order) buffer.push(x[i], v[i], m[i], chunk);
    buffer.flush(chunk);
  }

  const EventEngine<Linked>& e_;
  double t_;
  std::size_t seam_ = 0;
  bool sorted_ = true;
};

}  // namespace shockgas::particles::detail
