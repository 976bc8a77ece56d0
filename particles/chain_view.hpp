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

namespace shockgas::particles::detail {

// A ring position wrapped into [0, L): x - L floor(x / L), where a result that
// rounding leaves at L (or below 0) becomes 0.
inline double wrap_into(double x, double L) {
  const double w = x - L * std::floor(x / L);
  return w >= L || w < 0 ? 0.0 : w;
}

// A run of consecutive bodies of the chain.
struct ChainChunk {
  static constexpr std::size_t capacity = 1024;  // bodies per chunk: 32 KiB, stays in L1/L2
  const std::size_t* first = nullptr;            // index of each body's first particle
  const double* x = nullptr;                     // position [length]
  const double* v = nullptr;                     // velocity [length/time]
  const double* m = nullptr;                     // mass [mass]
  std::size_t size = 0;
};

class ChainView {
 public:
  using Sink = std::function<void(const ChainChunk&)>;
  virtual std::size_t size() const = 0;  // live bodies
  virtual void visit(const Sink& sink) const = 0;

 protected:
  ~ChainView() = default;
};

// A chunk being filled body by body.
class ChunkBuffer {
 public:
  void push(std::size_t first, double x, double v, double m) {
    first_[n_] = first, x_[n_] = x, v_[n_] = v, m_[n_] = m;
    ++n_;
  }
  bool full() const { return n_ == ChainChunk::capacity; }
  // Hands the buffered bodies to sink (if any) and empties the buffer.
  void flush(const ChainView::Sink& sink) {
    if (n_ > 0) sink(ChainChunk{first_.data(), x_.data(), v_.data(), m_.data(), n_});
    n_ = 0;
  }

 private:
  std::array<std::size_t, ChainChunk::capacity> first_;
  std::array<double, ChainChunk::capacity> x_, v_, m_;
  std::size_t n_ = 0;
};

// The view of a model that can list its bodies one at a time:
// for_each(f) calls f(first, x, v, m) for every live body in chain order.
template <class ForEach>
class BufferedChainView final : public ChainView {
 public:
  BufferedChainView(std::size_t size, ForEach for_each) : size_(size), for_each_(std::move(for_each)) {}
  std::size_t size() const override { return size_; }
  void visit(const Sink& sink) const override {
    ChunkBuffer buffer;
    for_each_([&](std::size_t first, double x, double v, double m) {
      buffer.push(first, x, v, m);
      if (buffer.full()) buffer.flush(sink);
    });
    buffer.flush(sink);
  }

 private:
  std::size_t size_;
  ForEach for_each_;
};

template <class ForEach>
BufferedChainView<ForEach> make_chain_view(std::size_t size, ForEach for_each) {
  return {size, std::move(for_each)};
}

}  // namespace shockgas::particles::detail
