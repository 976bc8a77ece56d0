#include "shockgas/core/initial_stream.hpp"

#include <algorithm>

namespace shockgas {

bool InitialStream::streamable(const InitialParams& p) {
  return (p.positions == "lattice" || p.positions == "random") &&
         (p.velocities == "uniform" || p.velocities == "gaussian");
}

InitialStream::InitialStream(const InitialParams& p, std::uint64_t realization)
    : n_(p.N),
      length_(domain_length(p)),
      amplitude_(p.amplitude),
      lattice_(p.positions == "lattice"),
      gaussian_(p.velocities == "gaussian"),
      rng_(realization_seed(p.seed, realization)) {
  if (!lattice_) {
    positions_.resize(n_);
    for (double& x : positions_) x = rng_.uniform(0.0, length_);
    std::sort(positions_.begin(), positions_.end());
  }
  if (p.remove_mean) {
    // As subtract_mean: momentum summed in order over unit masses, then / N.
    Rng replay = rng_;
    double momentum = 0;
    for (std::size_t i = 0; i < n_; ++i) momentum += 1.0 * draw_velocity(replay);
    mean_ = momentum / static_cast<double>(n_);
  }
}

double InitialStream::draw_velocity(Rng& rng) const {
  return gaussian_ ? amplitude_ * rng.normal() : rng.uniform(-amplitude_, amplitude_);
}

void InitialStream::next(std::size_t count, double* x, double* v, double* m) {
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = next_ + k;
    x[k] = lattice_ ? (i + 0.5) * length_ / n_ : positions_[i];
    v[k] = draw_velocity(rng_) - mean_;
    m[k] = 1.0;
  }
  next_ += count;
  if (next_ == n_) positions_ = std::vector<double>();  // the memory goes back now
}

}  // namespace shockgas
