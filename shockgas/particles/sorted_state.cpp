#include "shockgas/particles/sorted_state.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <limits>
#include <numeric>
#include <vector>

#include "shockgas/particles/ring_wrap.hpp"

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

// Calls f(k, wrapped x, v, m) for the bodies of the view at chain positions
// k = begin .. end - 1 (all by default), in chain order.
template <class F>
void for_each_wrapped(const ChainView& view, double L, bool ring, F&& f, std::size_t begin = 0,
                      std::size_t end = std::numeric_limits<std::size_t>::max()) {
  PeriodWrap wrap(L);
  std::size_t k = begin;
  view.visit(
      [&](const ChainChunk& c) {
        for (std::size_t i = 0; i < c.size; ++i, ++k) f(k, ring ? wrap(c.x[i]) : c.x[i], c.v[i], c.m[i]);
      },
      Fields::all, begin, std::min(end, view.size()));
}

// Bodies fed in order of arrival, handed on in the order of a stable sort by x
// through a window of `capacity` bodies kept sorted (a body goes after those of
// equal x already there). Exact as long as no body arrives below one already
// handed on: every body handed on is then the least of those left, and the
// later of equal ones. Otherwise failed(), and what was handed on is not the
// stable order.
class WindowedOrder {
 public:
  static constexpr std::size_t capacity = 4096;  // 96 KiB of bodies

  template <class Out>
  void push(double x, double v, double m, Out&& out) {
    if (x < last_out_) failed_ = true;
    if (failed_) return;
    if (window_.empty() || !(x < window_.back().x)) {
      window_.push_back({x, v, m});
    } else {
      const auto at = std::upper_bound(window_.begin(), window_.end(), x,
                                       [](double value, const Body& b) { return value < b.x; });
      window_.insert(at, {x, v, m});
    }
    if (window_.size() > capacity) pop(out);
  }
  template <class Out>
  void flush(Out&& out) {
    while (!failed_ && !window_.empty()) pop(out);
  }
  bool failed() const { return failed_; }

 private:
  struct Body {
    double x, v, m;
  };
  template <class Out>
  void pop(Out&& out) {
    const Body b = window_.front();
    window_.pop_front();
    last_out_ = b.x;
    out(b.x, b.v, b.m);
  }
  std::deque<Body> window_;
  double last_out_ = -std::numeric_limits<double>::infinity();
  bool failed_ = false;
};

// Calls f(x, v, m) for every body, wrapped, in chain order from the seam. One
// pass when at most `held` bodies lie before the seam (they wait in a buffer of
// at most 1.5 MiB until the rest has gone), else a visit from the seam to the
// end and one from the start up to the seam.
template <class F>
void from_seam(const ChainView& view, double L, bool ring, std::size_t seam, F&& f) {
  constexpr std::size_t held = std::size_t{1} << 16;
  if (seam <= held) {
    std::vector<std::array<double, 3>> before;
    before.reserve(seam);
    for_each_wrapped(view, L, ring, [&](std::size_t k, double x, double v, double m) {
      if (k < seam)
        before.push_back({x, v, m});
      else
        f(x, v, m);
    });
    for (const auto& [x, v, m] : before) f(x, v, m);
    return;
  }
  auto each = [&](std::size_t, double x, double v, double m) { f(x, v, m); };
  for_each_wrapped(view, L, ring, each, seam);
  for_each_wrapped(view, L, ring, each, 0, seam);
}

// b in the stable sort's order by x, in place through a WindowedOrder, if the
// window can order it (checked by a pass first); else b as it was and false.
// In place: the k-th body handed on is written to b[k] once more than the
// window's capacity have been read, so only bodies already read are overwritten.
bool ordered_in_place(Bodies& b) {
  WindowedOrder trial;
  for (std::size_t i = 0; i < b.size(); ++i)
    trial.push(b.x[i], b.v[i], b.m[i], [](double, double, double) {});
  if (trial.failed()) return false;
  WindowedOrder order;
  std::size_t k = 0;
  auto put = [&](double x, double v, double m) { b.x[k] = x, b.v[k] = v, b.m[k] = m, ++k; };
  for (std::size_t i = 0; i < b.size(); ++i) order.push(b.x[i], b.v[i], b.m[i], put);
  order.flush(put);
  return true;
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
  for (std::vector<double>* a : {&out.x, &out.v, &out.m})
    std::rotate(a->begin(), a->begin() + start, a->end());
  if (seam.sorted() || ordered_in_place(out)) return out;
  return stable_sorted(out);
}

// The last body from the seam is the one before it (at the seam's largest
// drop), or the chain's last where the seam is the chain's start.
SortedState::SortedState(const ChainView& view, double L, bool ring) : view_(view), L_(L), ring_(ring) {
  SeamSearch seam(ring);
  std::array<double, 3> previous{}, before_drop{};
  for_each_wrapped(view, L, ring, [&](std::size_t, double x, double v, double m) {
    const std::size_t drop = seam.largest_drop_at();
    seam.add(x);
    if (seam.largest_drop_at() != drop) before_drop = previous;
    previous = {x, v, m};
  });
  seam_ = seam.seam();
  sorted_ = seam.sorted();
  if (sorted_) {
    if (view.size() > 0) last_ = seam_ > 0 ? before_drop : previous;
    return;
  }
  WindowedOrder trial;
  from_seam(view, L, ring, seam_,
            [&](double x, double v, double m) { trial.push(x, v, m, [](double, double, double) {}); });
  windowed_ = !trial.failed();
}

void SortedState::read(const Chunk& chunk) const {
  ChunkBuffer buffer(chunk);
  auto put = [&](double x, double v, double m) { buffer.push(x, v, m); };
  if (sorted_) {
    from_seam(view_, L_, ring_, seam_, put);
  } else if (windowed_) {
    WindowedOrder order;
    from_seam(view_, L_, ring_, seam_, [&](double x, double v, double m) { order.push(x, v, m, put); });
    order.flush(put);
  } else {
    const Bodies b = sorted_bodies(view_, L_, ring_);
    for (std::size_t i = 0; i < b.size(); ++i) buffer.push(b.x[i], b.v[i], b.m[i]);
  }
  buffer.flush();
}

}  // namespace shockgas::particles::detail
