#include "shockgas/core/error.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace shockgas {

std::string printable(const std::string& text, bool lines) {
  static const char* const kNamed[] = {"\\0", nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                                       "\\a", "\\b",   "\\t",   "\\n",   "\\v",   "\\f",   "\\r"};
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    const bool c1 = c == 0xc2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
                    static_cast<unsigned char>(text[i + 1]) <= 0x9f;  // U+0080-U+009F in UTF-8
    if ((c >= 0x20 && c != 0x7f && !c1) || (lines && (c == '\n' || c == '\t'))) {
      out += text[i];
      continue;
    }
    const unsigned code = c1 ? static_cast<unsigned char>(text[++i]) : c;
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02x", code);
    out += code < sizeof kNamed / sizeof *kNamed && kNamed[code] ? kNamed[code] : buf;
  }
  return out;
}

namespace {
// Every part printable(): a key or value read from a file or the command line
// may hold any byte.
std::string compose(const std::string& key, const std::string& value, const std::string& allowed,
                    const std::string& where) {
  std::string msg = where.empty() ? "" : where + ": ";
  msg += key + " = " + value + " is not allowed; allowed: " + allowed;
  return printable(msg);
}
}  // namespace

InputError::InputError(std::string key, std::string value, std::string allowed, std::string where)
    : std::runtime_error(compose(key, value, allowed, where)),
      key_(std::move(key)),
      value_(std::move(value)),
      allowed_(std::move(allowed)),
      where_(std::move(where)) {}

InputError::InputError(std::string key, std::string value, std::string allowed, std::string where,
                       Message message)
    : std::runtime_error(printable(message.text)),
      key_(std::move(key)),
      value_(std::move(value)),
      allowed_(std::move(allowed)),
      where_(std::move(where)) {}

InputError InputError::located(const std::string& where) const {
  return InputError(key_, value_, allowed_, where);
}

// The shortest text that reads back as `value`.
std::string to_text(double value) {
  char buf[64];
#if defined(__cpp_lib_to_chars)
  auto res = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, res.ptr);
#else
  // Without std::to_chars for doubles (libc++ 14, the lab's WebAssembly build):
  // the fewest %g digits that read back to the same double.
  for (int digits = 1; digits < 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    if (std::strtod(buf, nullptr) == value) return buf;
  }
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
#endif
}

std::string to_text(double value, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, value);
  return buf;
}

void require_in_range(const std::string& key, double value, double lo, double hi) {
  if (!(std::isfinite(value) && value >= lo && value <= hi))
    throw InputError(key, to_text(value), "a finite number in [" + to_text(lo) + ", " + to_text(hi) + "]");
}

void require_above(const std::string& key, double value, double lo) {
  if (!(std::isfinite(value) && value > lo))
    throw InputError(key, to_text(value), "a finite number > " + to_text(lo));
}

}  // namespace shockgas
