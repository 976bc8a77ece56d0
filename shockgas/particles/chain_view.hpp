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
// bodies in the same order each time, in chunks of at most ChainChunk::capacity;
// a visit of the chain positions [begin, end) delivers those of them only.
#include <array>
#include <cstddef>
#include <functional>

namespace shockgas::particles::detail {

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
  // The bodies at chain positions begin .. end - 1 (begin <= end <= size()).
  virtual void visit(const Sink& sink, Fields fields, std::size_t begin, std::size_t end) const = 0;
  void visit(const Sink& sink, Fields fields) const { visit(sink, fields, 0, size()); }

 protected:
  ~ChainView() = default;
};

// The view of a model that can list its bodies one at a time:
// for_each(f, begin, end) calls f(first, x, v, m) for the live bodies at chain
// positions begin .. end - 1, in chain order.
template <class ForEach>
class BufferedChainView final : public ChainView {
 public:
  BufferedChainView(std::size_t size, ForEach for_each) : size_(size), for_each_(std::move(for_each)) {}
  using ChainView::visit;
  std::size_t size() const override { return size_; }
  void visit(const Sink& sink, Fields fields, std::size_t begin, std::size_t end) const override {
    fields == Fields::all ? fill<true>(sink, begin, end) : fill<false>(sink, begin, end);
  }

 private:
  // Chunks filled in a buffer on the stack; the count kept in a local (a member
  // would be reloaded after every store into the arrays).
  template <bool All>
  void fill(const Sink& sink, std::size_t begin, std::size_t end) const {
    constexpr std::size_t capacity = ChainChunk::capacity;
    std::array<std::size_t, capacity> first;
    std::array<double, capacity> x, v, m;
    std::size_t n = 0;
    auto flush = [&] {
      if (n > 0) sink(ChainChunk{first.data(), x.data(), v.data(), m.data(), n});
      n = 0;
    };
    for_each_(
        [&](std::size_t i, double xi, double vi, double mi) {
          if constexpr (All) first[n] = i, x[n] = xi;
          v[n] = vi, m[n] = mi;
          if (++n == capacity) flush();
        },
        begin, end);
    flush();
  }

  std::size_t size_;
  ForEach for_each_;
};

template <class ForEach>
BufferedChainView<ForEach> make_chain_view(std::size_t size, ForEach for_each) {
  return {size, std::move(for_each)};
}

// The view of an event engine's live bodies at time t (EventEngine::for_each_body).
template <class Engine>
auto engine_chain_view(const Engine& engine, double t) {
  return make_chain_view(engine.alive(), [&engine, t](auto&& f, std::size_t begin, std::size_t end) {
    engine.for_each_body(t, f, begin, end);
  });
}

}  // namespace shockgas::particles::detail
