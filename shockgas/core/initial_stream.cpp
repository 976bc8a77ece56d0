#include "shockgas/core/initial_stream.hpp"

#include <algorithm>
#if __has_include(<boost/sort/pdqsort/pdqsort.hpp>)
#include <boost/sort/pdqsort/pdqsort.hpp>
#define SHOCKGAS_HAS_PDQSORT 1
#endif

namespace shockgas {

namespace {

// Any correct sort gives the same sequence; pattern-defeating quicksort
// (Peters 2021) takes about 50 ns per position against std::sort's 120.
// Without Boost (the lab's WebAssembly build): std::sort, the same sequence.
void sort_positions(std::vector<double>& x) {
#if defined(SHOCKGAS_HAS_PDQSORT)
  boost::sort::pdqsort(x.begin(), x.end());
#else
  std::sort(x.begin(), x.end());
#endif
}

}  // namespace

bool InitialStream::streamable(const InitialParams& p) {
  return p.velocities == Velocities::uniform || p.velocities == Velocities::gaussian;
}

InitialStream::InitialStream(const InitialParams& p, std::uint64_t realization, Parts parts)
    : n_(p.N),
      length_(domain_length(p)),
      amplitude_(p.amplitude),
      lattice_(p.positions == Positions::lattice),
      gaussian_(p.velocities == Velocities::gaussian),
      positions_wanted_(parts == Parts::all),
      rng_(realization_seed(p.seed, realization)) {
  if (!lattice_ && positions_wanted_) {
    positions_.resize(n_);
    for (double& x : positions_) x = rng_.uniform(0.0, length_);
    sort_positions(positions_);
  } else if (!lattice_) {
    for (std::size_t i = 0; i < n_; ++i) rng_.next();  // one draw per position, as above
  }
  if (p.remove_mean) {
    // As subtract_mean: momentum summed in order over unit masses, then / N.
    Rng replay = rng_;
    double momentum = 0;
    for (std::size_t i = 0; i < n_; ++i) momentum += 1.0 * draw_velocity(replay);
    mean_ = momentum / static_cast<double>(n_);
  }
}

InitialStream::InitialStream(const Bodies& held) : held_(&held), n_(held.size()) {}

double InitialStream::mean_mass() const {
  return held_ ? total_mass(*held_) / static_cast<double>(n_) : 1.0;  // drawn: m = 1 (next)
}

double InitialStream::draw_velocity(Rng& rng) const {
  return gaussian_ ? amplitude_ * rng.normal() : rng.uniform(-amplitude_, amplitude_);
}

void InitialStream::next(std::size_t count, double* x, double* v, double* m) {
  if (held_) {
    std::copy_n(held_->x.begin() + next_, count, x);
    std::copy_n(held_->v.begin() + next_, count, v);
    std::copy_n(held_->m.begin() + next_, count, m);
    next_ += count;
    return;
  }
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = next_ + k;
    if (positions_wanted_) x[k] = lattice_ ? (i + 0.5) * length_ / n_ : positions_[i];
    v[k] = draw_velocity(rng_) - mean_;
    m[k] = 1.0;
  }
  next_ += count;
  if (next_ == n_) positions_ = std::vector<double>();  // the memory goes back now
}

InitialStream stream_realization(const InitialCondition& initial, std::uint64_t k,
                                 InitialStream::Parts parts) {
  if (initial.holds_bodies() && (k == 0 || !initial.depends_on_realization()))
    return InitialStream(initial.bodies());
  return InitialStream(initial.params(), k, parts);
}

double initial_temperature(const InitialCondition& initial, std::uint64_t k) {
  TemperatureSums sums;
  InitialStream drawn = stream_realization(initial, k, InitialStream::Parts::velocities);
  read_in_chunks(drawn, [&](const double*, const double* v, const double* m, std::size_t count) {
    sums.add(v, m, count);
  });
  return sums.temperature();
}

}  // namespace shockgas
