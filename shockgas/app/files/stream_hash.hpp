#pragma once
// A checksum of a byte stream that may arrive in pieces (private to app/): the
// run state files (run_state_file.hpp) and realization 0's state files
// (state_file.hpp).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace shockgas::app {

// FNV-1a (Fowler, Noll, Vo) over the stream's 64-bit words, the last partial
// word byte by byte: a change of any byte changes it, at about 2 GB/s, and the
// same for any split of the stream into pieces.
class StreamHash {
 public:
  void add(const char* p, std::size_t n) {
    if (carried_ > 0) {  // complete the carried word
      const std::size_t take = std::min(n, 8 - carried_);
      std::memcpy(carry_ + carried_, p, take);
      carried_ += take, p += take, n -= take;
      if (carried_ < 8) return;
      word(carry_), carried_ = 0;
    }
    for (; n >= 8; p += 8, n -= 8) word(p);
    std::memcpy(carry_, p, n);
    carried_ = n;
  }
  std::uint64_t value() const {
    std::uint64_t h = h_;
    for (std::size_t k = 0; k < carried_; ++k) h = (h ^ static_cast<unsigned char>(carry_[k])) * kPrime;
    return h;
  }

 private:
  static constexpr std::uint64_t kPrime = 1099511628211ull;
  void word(const char* p) {
    std::uint64_t w;
    std::memcpy(&w, p, 8);
    h_ = (h_ ^ w) * kPrime;
  }
  std::uint64_t h_ = 14695981039346656037ull;
  char carry_[8] = {};
  std::size_t carried_ = 0;
};

}  // namespace shockgas::app
