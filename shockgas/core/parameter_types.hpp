#pragma once
// How each parameter type is read from a ParameterValue, checked, written back
// and described (see parameters.hpp, which includes this file).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "shockgas/core/enum_names.hpp"
#include "shockgas/core/parameters.hpp"

namespace shockgas {

namespace detail {

// Readers: the value's type and rule checked; InputError(key, written, allowed) otherwise.
double read_number(const ParameterValue& v, const std::string& key, const Allowed& rule);
std::uint64_t read_integer(const ParameterValue& v, const std::string& key, const Allowed& rule);
bool read_boolean(const ParameterValue& v, const std::string& key);
std::string read_text(const ParameterValue& v, const std::string& key, const Allowed& rule);
const std::string& read_name(const ParameterValue& v, const std::string& key, const std::string& allowed);

// The rule on a typed value (InputError with the value as text).
void check_number(double x, const std::string& key, const Allowed& rule);
void check_integer(std::uint64_t x, const std::string& key, const Allowed& rule);
void check_text(const std::string& s, const std::string& key, const Allowed& rule);

// Allowed values in words.
std::string number_text(const Allowed& rule);
std::string integer_text(const Allowed& rule);
std::string text_text(const Allowed& rule);

}  // namespace detail

template <>
struct ParameterType<double> {
  static std::string kind() { return "number"; }
  static std::string allowed_text(const Allowed& r) { return detail::number_text(r); }
  static double read(const ParameterValue& v, const std::string& key, const Allowed& r) {
    return detail::read_number(v, key, r);
  }
  static void check(double x, const std::string& key, const Allowed& r) { detail::check_number(x, key, r); }
  static ParameterValue write(double x) { return ParameterValue::of(x); }
};

template <>
struct ParameterType<std::uint64_t> {
  static std::string kind() { return "integer"; }
  static std::string allowed_text(const Allowed& r) { return detail::integer_text(r); }
  static std::uint64_t read(const ParameterValue& v, const std::string& key, const Allowed& r) {
    return detail::read_integer(v, key, r);
  }
  static void check(std::uint64_t x, const std::string& key, const Allowed& r) {
    detail::check_integer(x, key, r);
  }
  static ParameterValue write(std::uint64_t x) { return ParameterValue::of(static_cast<std::int64_t>(x)); }
};

// std::size_t where it is a type of its own (32-bit targets such as the lab's
// WebAssembly build; on 64-bit Linux it is std::uint64_t, above): an integer
// that must also fit in std::size_t.
#if SIZE_MAX != UINT64_MAX
template <>
struct ParameterType<std::size_t> {
  using Wide = ParameterType<std::uint64_t>;
  static std::string kind() { return Wide::kind(); }
  static std::string allowed_text(const Allowed& r) { return Wide::allowed_text(r); }
  static std::size_t read(const ParameterValue& v, const std::string& key, const Allowed& r) {
    const std::uint64_t x = Wide::read(v, key, r);
    if (x > SIZE_MAX) throw InputError(key, v.written, "at most " + std::to_string(SIZE_MAX));
    return static_cast<std::size_t>(x);
  }
  static void check(std::size_t x, const std::string& key, const Allowed& r) { Wide::check(x, key, r); }
  static ParameterValue write(std::size_t x) { return Wide::write(x); }
};
#endif

template <>
struct ParameterType<bool> {
  static std::string kind() { return "boolean"; }
  static std::string allowed_text(const Allowed&) { return "true or false"; }
  static bool read(const ParameterValue& v, const std::string& key, const Allowed&) {
    return detail::read_boolean(v, key);
  }
  static void check(bool, const std::string&, const Allowed&) {}
  static ParameterValue write(bool b) { return ParameterValue::of(b); }
};

template <>
struct ParameterType<std::string> {
  static std::string kind() { return "string"; }
  static std::string allowed_text(const Allowed& r) { return detail::text_text(r); }
  static std::string read(const ParameterValue& v, const std::string& key, const Allowed& r) {
    return detail::read_text(v, key, r);
  }
  static void check(const std::string& s, const std::string& key, const Allowed& r) {
    detail::check_text(s, key, r);
  }
  static ParameterValue write(const std::string& s) { return ParameterValue::of(s); }
};

// An enum: a string, one of its declared names.
template <NamedEnum E>
struct ParameterType<E> {
  static std::string kind() { return "string"; }
  static std::string allowed_text(const Allowed& r) {
    return r.text.empty() ? choices_text(enum_choices<E>()) : r.text;
  }
  static E read(const ParameterValue& v, const std::string& key, const Allowed& r) {
    const std::string& name = detail::read_name(v, key, allowed_text(r));
    for (const auto& entry : enum_names(E{}))
      if (name == entry.name) return entry.value;
    throw InputError(key, v.written, allowed_text(r));
  }
  static void check(E, const std::string&, const Allowed&) {}
  static ParameterValue write(E e) { return ParameterValue::of(name_of(e)); }
};

// A list; a single value stands for a list of one.
template <class T>
struct ParameterType<std::vector<T>> {
  using Item = ParameterType<T>;
  static std::string kind() { return "list of " + Item::kind() + "s"; }
  static std::string allowed_text(const Allowed& r) {
    if (!r.text.empty()) return r.text;
    if (r.names) return "a list from " + choices_text(r.names());
    return "a list of values, each " + Item::allowed_text(r);
  }
  static std::vector<T> read(const ParameterValue& v, const std::string& key, const Allowed& r) {
    std::vector<T> out;
    try {
      if (v.type != ParameterValue::Type::list) return {Item::read(v, key, r)};
      for (const ParameterValue& item : v.items) out.push_back(Item::read(item, key, r));
    } catch (const InputError& e) {
      throw InputError(key, e.value(), allowed_text(r));  // the list's rule, not the item's
    }
    return out;
  }
  static void check(const std::vector<T>& xs, const std::string& key, const Allowed& r) {
    try {
      for (const T& x : xs) Item::check(x, key, r);
    } catch (const InputError& e) {
      throw InputError(key, e.value(), allowed_text(r));
    }
  }
  static ParameterValue write(const std::vector<T>& xs) {
    std::vector<ParameterValue> items;
    for (const T& x : xs) items.push_back(Item::write(x));
    return ParameterValue::list(std::move(items));
  }
};

}  // namespace shockgas
