#include "sorted_state.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

#include "ring_wrap.hpp"

namespace shockgas::particles::detail {

namespace {

// b reordered by a stable sort on x.
Bodies stable_sorted(const Bodies& b) {
  std::vector<std::size_t> order(b.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return b.x[i] < b.x[j]; });
  Bodies out;
  out.reserve(b.size());
  for (std::size_t k : order) out.push_back(b.x[k], b.v[k], b.m[k]);
  return out;
}

// Bodies handed on in chunks of ChainChunk::capacity.
class ChunkBuffer {
 public:
  explicit ChunkBuffer(const StateReader::Chunk& chunk) : chunk_(chunk) {}
  void push(double x, double v, double m) {
    x_[n_] = x, v_[n_] = v, m_[n_] = m;
    if (++n_ == x_.size()) flush();
  }
  void flush() {
    if (n_ > 0) chunk_(x_.data(), v_.data(), m_.data(), n_);
    n_ = 0;
  }

 private:
  const StateReader::Chunk& chunk_;
  std::array<double, ChainChunk::capacity> x_, v_, m_;
  std::size_t n_ = 0;
};

// Calls f(k, wrapped x, v, m) for every body of the view, k in chain order.
template <class F>
void for_each_wrapped(const ChainView& view, double L, bool ring, F&& f) {
  PeriodWrap wrap(L);
  std::size_t k = 0;
  view.visit(
      [&](const ChainChunk& c) {
        for (std::size_t i = 0; i < c.size; ++i, ++k) f(k, ring ? wrap(c.x[i]) : c.x[i], c.v[i], c.m[i]);
      },
      Fields::all);
}

}  // namespace

Bodies sorted_bodies(const ChainView& s, double L, bool ring) {
  Bodies out;
  out.reserve(s.size());
  SeamSearch seam(ring);
  for_each_wrapped(s, L, ring, [&](std::size_t, double x, double v, double m) {
    seam.add(x);
    out.push_back(x, v, m);
  });
  const auto start = static_cast<std::ptrdiff_t>(seam.seam());
  for (std::vector<double>* a : {&out.x, &out.v, &out.m}) std::rotate(a->begin(), a->begin() + start, a->end());
  return seam.sorted() ? out : stable_sorted(out);
}

SortedState::SortedState(const ChainView& view, double L, bool ring) : view_(view), L_(L), ring_(ring) {
  SeamSearch seam(ring);
  for_each_wrapped(view, L, ring, [&](std::size_t, double x, double, double) { seam.add(x); });
  seam_ = seam.seam();
  sorted_ = seam.sorted();
}

void SortedState::read(const Chunk& chunk) const {
  ChunkBuffer buffer(chunk);
  if (!sorted_) {
    const Bodies b = sorted_bodies(view_, L_, ring_);
    for (std::size_t i = 0; i < b.size(); ++i) buffer.push(b.x[i], b.v[i], b.m[i]);
  } else {
    for (const bool from_seam : {true, false})
      for_each_wrapped(view_, L_, ring_, [&](std::size_t k, double x, double v, double m) {
        if ((k >= seam_) == from_seam) buffer.push(x, v, m);
      });
  }
  buffer.flush();
}

}  // namespace shockgas::particles::detail
