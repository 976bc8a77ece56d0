#pragma once
// Bytes of numbers and texts, each length-prefixed (std::uint64_t, native byte
// order: the bytes stay on one kind of machine): the form of a realization
// record in a message (realization_record.hpp) and of a checkpoint file
// (checkpoint.hpp).
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "shockgas/core/error.hpp"

namespace shockgas::app {

class ByteWriter {
 public:
  void u64(std::uint64_t x) { raw(&x, sizeof x); }
  void text(const std::string& s) { u64(s.size()), raw(s.data(), s.size()); }
  void numbers(const std::vector<double>& d) { u64(d.size()), raw(d.data(), d.size() * sizeof(double)); }
  const std::string& bytes() const { return out_; }
  std::string take() { return std::move(out_); }

 private:
  void raw(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
  std::string out_;
};

// Reads what a ByteWriter wrote; RunError "<what>: truncated" when the bytes end early.
class ByteReader {
 public:
  ByteReader(const std::string& in, std::string what) : in_(in), what_(std::move(what)) {}
  bool done() const { return at_ == in_.size(); }
  std::size_t position() const { return at_; }
  std::uint64_t u64() {
    std::uint64_t x;
    raw(&x, sizeof x);
    return x;
  }
  std::string text() {
    std::string s(checked_count(u64(), 1), '\0');
    raw(s.data(), s.size());
    return s;
  }
  std::vector<double> numbers() {
    std::vector<double> d(checked_count(u64(), sizeof(double)));
    raw(d.data(), d.size() * sizeof(double));
    return d;
  }

 private:
  std::size_t checked_count(std::uint64_t n, std::size_t size) const {
    if (n > (in_.size() - at_) / size) throw RunError(what_ + ": truncated");
    return static_cast<std::size_t>(n);
  }
  void raw(void* p, std::size_t n) {
    if (n > in_.size() - at_) throw RunError(what_ + ": truncated");
    if (n == 0) return;  // p may be an empty vector's null data()
    std::memcpy(p, in_.data() + at_, n);
    at_ += n;
  }
  const std::string& in_;
  std::string what_;
  std::size_t at_ = 0;
};

}  // namespace shockgas::app
