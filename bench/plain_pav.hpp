#pragma once
// A plain pool-adjacent-violators pass, the baseline of the exact sticky hull
// (bench/hull_bench.cpp, bench/plain_pav_command.cpp): the isotonic regression
// of y_i = x_i + t v_i with weights m_i as the textbook stack of blocks (mean,
// weight), a new point pooled by weighted means with the blocks above it. The
// least any hull must do: it yields neither velocities nor members.
#include <cstddef>
#include <memory>

namespace shockgas::bench {

class PlainPav {
 public:
  explicit PlainPav(std::size_t capacity)
      : mean_(std::make_unique_for_overwrite<double[]>(capacity)),
        weight_(std::make_unique_for_overwrite<double[]>(capacity)) {}

  // The next point, y after every earlier one, of weight w > 0.
  void push(double y, double w) {
    while (top_ > 0 && mean_[top_ - 1] > y) {
      const double total = weight_[top_ - 1] + w;
      y = (weight_[top_ - 1] * mean_[top_ - 1] + w * y) / total;
      w = total;
      --top_;
    }
    mean_[top_] = y, weight_[top_] = w;
    ++top_;
  }

  std::size_t blocks() const { return top_; }

 private:
  std::unique_ptr<double[]> mean_, weight_;
  std::size_t top_ = 0;
};

}  // namespace shockgas::bench
