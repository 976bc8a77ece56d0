// Reading, checking and describing declared parameters (shockgas/core/parameters.hpp).
#include "shockgas/core/parameters.hpp"

#include <cmath>

namespace shockgas {

std::string choices_text(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? " or " : ", ";
    text += "\"" + names[i] + "\"";
  }
  return text;
}

ParameterValue ParameterValue::of(bool b) {
  ParameterValue v;
  v.type = Type::boolean;
  v.boolean = b;
  v.written = b ? "true" : "false";
  return v;
}

ParameterValue ParameterValue::of(std::int64_t i) {
  ParameterValue v;
  v.type = Type::integer;
  v.integer = i;
  v.written = std::to_string(i);
  return v;
}

ParameterValue ParameterValue::of(double x) {
  ParameterValue v;
  v.type = Type::number;
  v.number = x;
  v.written = to_text(x);
  return v;
}

ParameterValue ParameterValue::of(const std::string& s) {
  ParameterValue v;
  v.type = Type::text;
  v.text = s;
  v.written = to_text(s);
  return v;
}

ParameterValue ParameterValue::list(std::vector<ParameterValue> items) {
  ParameterValue v;
  v.type = Type::list;
  v.written = "[";
  for (std::size_t i = 0; i < items.size(); ++i) v.written += (i ? ", " : "") + items[i].written;
  v.written += "]";
  v.items = std::move(items);
  return v;
}

bool Bounds::contains(double x) const {
  if (!std::isfinite(x)) return false;
  const bool lo_ok = lo_open ? x > lo : x >= lo;
  const bool hi_ok = hi_open ? x < hi : x <= hi;
  return lo_ok && hi_ok;
}

std::string Bounds::text(const std::string& what) const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (has_lo && has_hi)
    return what + " in " + (lo_open ? "(" : "[") + to_text(lo) + ", " + to_text(hi) + (hi_open ? ")" : "]");
  if (has_lo) return what + (lo_open ? " > " : " >= ") + to_text(lo);
  if (has_hi) return what + (hi_open ? " < " : " <= ") + to_text(hi);
  return what;
}

Bounds at_least(double lo) { return Bounds{lo, std::numeric_limits<double>::infinity(), false, false}; }
Bounds above(double lo) { return Bounds{lo, std::numeric_limits<double>::infinity(), true, false}; }
Bounds between(double lo, double hi) { return Bounds{lo, hi, false, false}; }
Bounds above_up_to(double lo, double hi) { return Bounds{lo, hi, true, false}; }

namespace detail {

namespace {

[[noreturn]] void refuse(const std::string& key, const ParameterValue& v, const std::string& allowed) {
  throw InputError(key, v.written, allowed);
}

bool is_one_of(const std::string& s, const std::vector<std::string>& names) {
  for (const auto& n : names)
    if (s == n) return true;
  return false;
}

}  // namespace

std::string number_text(const Allowed& r) {
  return r.text.empty() ? r.bounds.text("a finite number") : r.text;
}
std::string integer_text(const Allowed& r) { return r.text.empty() ? r.bounds.text("an integer") : r.text; }

std::string text_text(const Allowed& r) {
  if (!r.text.empty()) return r.text;
  return r.names ? "one of " + choices_text(r.names()) : "any text";
}

double read_number(const ParameterValue& v, const std::string& key, const Allowed& r) {
  double x = 0;
  if (v.type == ParameterValue::Type::number)
    x = v.number;
  else if (v.type == ParameterValue::Type::integer)
    x = static_cast<double>(v.integer);
  else
    refuse(key, v, number_text(r));
  if (!r.bounds.contains(x)) refuse(key, v, number_text(r));
  return x;
}

// A whole number, written as an integer or as a float (1e6); below 2^63.
std::uint64_t read_integer(const ParameterValue& v, const std::string& key, const Allowed& r) {
  double x = 0;
  if (v.type == ParameterValue::Type::integer)
    x = static_cast<double>(v.integer);
  else if (v.type == ParameterValue::Type::number && v.number == std::floor(v.number) &&
           std::abs(v.number) < 9e18)
    x = v.number;
  else if (v.type == ParameterValue::Type::number && v.number == std::floor(v.number))
    refuse(key, v, integer_text(r) + " (a whole float only below 9e18: write a larger one as an integer)");
  else
    refuse(key, v, integer_text(r));
  if (x < 0 || !r.bounds.contains(x)) refuse(key, v, integer_text(r));
  return v.type == ParameterValue::Type::integer ? static_cast<std::uint64_t>(v.integer)
                                                 : static_cast<std::uint64_t>(x);
}

bool read_boolean(const ParameterValue& v, const std::string& key) {
  if (v.type != ParameterValue::Type::boolean) refuse(key, v, "a boolean (true or false)");
  return v.boolean;
}

std::string read_text(const ParameterValue& v, const std::string& key, const Allowed& r) {
  if (v.type != ParameterValue::Type::text) refuse(key, v, "a string: " + text_text(r));
  if (r.names && !is_one_of(v.text, r.names())) refuse(key, v, text_text(r));
  return v.text;
}

const std::string& read_name(const ParameterValue& v, const std::string& key, const std::string& allowed) {
  if (v.type != ParameterValue::Type::text) refuse(key, v, allowed);
  return v.text;
}

void check_number(double x, const std::string& key, const Allowed& r) {
  if (!r.bounds.contains(x)) throw InputError(key, to_text(x), number_text(r));
}

void check_integer(std::uint64_t x, const std::string& key, const Allowed& r) {
  if (!r.bounds.contains(static_cast<double>(x))) throw InputError(key, to_text(x), integer_text(r));
}

void check_text(const std::string& s, const std::string& key, const Allowed& r) {
  if (r.names && !is_one_of(s, r.names())) throw InputError(key, to_text(s), text_text(r));
}

}  // namespace detail

}  // namespace shockgas
