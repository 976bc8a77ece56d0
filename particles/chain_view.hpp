#pragma once
// How a model hands its state to the recorder (private to particles/): a view
// of the live bodies in chain order, streamed in chunks, never copied whole.
//
// Chain order: increasing index of each body's first original particle. Body b
// holds the particles first[b] .. first[b+1]-1; on a ring the last body also
// those before the first body's first. Positions may be unrolled (the engine
// never wraps them) or wrapped into [0, L) (the hull); the recorder wraps them.
//
// Contract: visit() may be called several times per stop and delivers the same
// bodies in the same order each time, in chunks of at most ChainChunk::capacity.
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>

namespace shockgas::particles::detail {

// A ring position wrapped into [0, L): x - L floor(x / L), where a result that
// rounding leaves at L (or below 0) becomes 0.
inline double wrap_into(double x, double L) {
  const double w = x - L * std::floor(x / L);
  return w >= L || w < 0 ? 0.0 : w;
}

// wrap_into(x, L) for positions that mostly stay in one period, as the chain's
// do: the division and floor only when x leaves the period of the previous one.
// Inside [k L + e, (k + 1) L - e), e = 2^-40 L, floor(x / L) is k whatever the
// rounding of x / L (for |k| < 2^10; beyond, every x takes the division), and
// x - L k is the same expression: the result is wrap_into's, to the bit.
class PeriodWrap {
 public:
  explicit PeriodWrap(double L) : L_(L) {}
  double operator()(double x) {
    if (!(x >= lo_ && x < hi_)) enter(x);
    const double w = x - L_ * k_;
    return w >= L_ || w < 0 ? 0.0 : w;
  }

 private:
  void enter(double x) {
    k_ = std::floor(x / L_);
    const double e = 0x1p-40 * L_;
    const bool near = std::abs(k_) < 0x1p10;
    lo_ = near ? L_ * k_ + e : inf;
    hi_ = near ? L_ * (k_ + 1) - e : -inf;
  }
  static constexpr double inf = std::numeric_limits<double>::infinity();
  double L_, k_ = 0, lo_ = inf, hi_ = -inf;  // [lo_, hi_): x with floor(x / L) = k_; empty at first
};

// A run of consecutive bodies of the chain.
struct ChainChunk {
  static constexpr std::size_t capacity = 1024;  // bodies per chunk: 32 KiB, stays in L1/L2
  const std::size_t* first = nullptr;            // index of each body's first particle
  const double* x = nullptr;                     // position [length]
  const double* v = nullptr;                     // velocity [length/time]
  const double* m = nullptr;                     // mass [mass]
  std::size_t size = 0;
};

// What a visit needs: every field, or the velocities and masses only (first
// and x are then left unset, and a view may skip computing them).
enum class Fields : unsigned char { all, velocities };

class ChainView {
 public:
  using Sink = std::function<void(const ChainChunk&)>;
  virtual std::size_t size() const = 0;  // live bodies
  virtual void visit(const Sink& sink, Fields fields) const = 0;

 protected:
  ~ChainView() = default;
};

// The view of a model that can list its bodies one at a time:
// for_each(f) calls f(first, x, v, m) for every live body in chain order.
template <class ForEach>
class BufferedChainView final : public ChainView {
 public:
  BufferedChainView(std::size_t size, ForEach for_each) : size_(size), for_each_(std::move(for_each)) {}
  std::size_t size() const override { return size_; }
  void visit(const Sink& sink, Fields fields) const override {
    fields == Fields::all ? fill<true>(sink) : fill<false>(sink);
  }

 private:
  // Chunks filled in a buffer on the stack; the count kept in a local (a member
  // would be reloaded after every store into the arrays).
  template <bool All>
  void fill(const Sink& sink) const {
    constexpr std::size_t capacity = ChainChunk::capacity;
    std::array<std::size_t, capacity> first;
    std::array<double, capacity> x, v, m;
    std::size_t n = 0;
    auto flush = [&] {
      if (n > 0) sink(ChainChunk{first.data(), x.data(), v.data(), m.data(), n});
      n = 0;
    };
    for_each_([&](std::size_t i, double xi, double vi, double mi) {
      if constexpr (All) first[n] = i, x[n] = xi;
      v[n] = vi, m[n] = mi;
      if (++n == capacity) flush();
    });
    flush();
  }

  std::size_t size_;
  ForEach for_each_;
};

template <class ForEach>
BufferedChainView<ForEach> make_chain_view(std::size_t size, ForEach for_each) {
  return {size, std::move(for_each)};
}

}  // namespace shockgas::particles::detail
