#pragma once
// The one checked-error path of shockgas.
//
//  * InputError: the input (a scene key, a command-line value, a file) is not
//    allowed. It names the key, the value and what is allowed; the command maps
//    it to exit code 2 and writes nothing.
//  * RunError: a run failed after it started (a non-finite value, a solver that
//    did not converge). The command maps it to exit code 1.
//
// Invariants that only a bug can break use assert(), not these.
#include <sstream>
#include <stdexcept>
#include <string>

namespace shockgas {

class InputError : public std::runtime_error {
 public:
  // key: dotted scene key ("particles.r"); value: the offending value as text;
  // allowed: what would have been accepted ("0 <= r <= 1"); where: "file:line" or "".
  InputError(std::string key, std::string value, std::string allowed, std::string where = "");

  const std::string& key() const { return key_; }
  const std::string& value() const { return value_; }
  const std::string& allowed() const { return allowed_; }
  const std::string& where() const { return where_; }

  // The same error located in a file ("scene.toml:12").
  InputError located(const std::string& where) const;

 protected:
  // For an error whose message is written whole rather than composed
  // (shockgas/app/files/file_problem.hpp); it survives copies as InputError.
  struct Message {
    std::string text;
  };
  InputError(std::string key, std::string value, std::string allowed, std::string where, Message message);

 private:
  std::string key_, value_, allowed_, where_;
};

class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// text as a terminal shows it safely: every control character (C0, DEL and the
// C1 range U+0080-U+009F) written as an escape ("\n", "\x1b", "\0"), so
// that a value from a file or the command line can neither end a message early
// (NUL) nor move the cursor or change the terminal; with lines, newlines and
// tabs are kept (a scene's text, shown as it is). Other bytes (UTF-8) are kept.
std::string printable(const std::string& text, bool lines = false);

// Value as text for error messages (shortest round-trip form for doubles).
std::string to_text(double value);
// A double to `digits` significant digits ("%.*g": 4.5e+12, 3035.43).
std::string to_text(double value, int digits);
inline std::string to_text(const std::string& value) { return "\"" + printable(value) + "\""; }
template <class Int>
requires std::is_integral_v<Int> std::string to_text(Int value) { return std::to_string(value); }

// Throws InputError(key, value, allowed) unless ok.
template <class T>
void require(bool ok, const std::string& key, const T& value, const std::string& allowed) {
  if (!ok) throw InputError(key, to_text(value), allowed);
}

// Throws unless value is finite and lo <= value <= hi.
void require_in_range(const std::string& key, double value, double lo, double hi);
// Throws unless value is finite and value > lo.
void require_above(const std::string& key, double value, double lo);

}  // namespace shockgas
