#pragma once
// Parameters declared once, beside the struct that holds them (the pattern of
// deal.II's ParameterAcceptor::add_parameter): the default lives in the member,
// and one declaration per member carries its scene key, unit, allowed values and
// a one-line doc:
//
//   struct ParticleParams { double r = 0.9; ... };
//   table.add(&ParticleParams::r, "r", "1", "restitution coefficient", between(0.0, 1.0));
//
// Everything that reads, checks, prints or documents a parameter goes through
// its declaration: the scene parser, validate(), `shockgas scene --defaults`
// and docs/scenes.md. There is no file format here: a reader (the scene parser,
// a binding) hands values over as ParameterValue.
//
// Types: double ("number": finite, within Bounds), std::uint64_t ("integer":
// whole numbers, also written as 1e6, within Bounds), bool, std::string (free
// text, or one of a set of names known at run time), an enum with declared names
// (shockgas/core/enum_names.hpp), and std::vector of those (a single value stands for a
// list of one). A value of the wrong type or outside what is allowed is an
// InputError naming "table.key", the value as written and what is allowed.
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "shockgas/core/enum_names.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas {

// A value as a reader found it, before it is typed.
struct ParameterValue {
  enum class Type { boolean, integer, number, text, list, other };
  Type type = Type::other;
  bool boolean = false;
  std::int64_t integer = 0;
  double number = 0;
  std::string text;
  std::vector<ParameterValue> items;  // Type::list
  std::string written;                // the value as written (for messages)

  static ParameterValue of(bool b);
  static ParameterValue of(std::int64_t i);
  static ParameterValue of(double x);
  static ParameterValue of(const std::string& s);
  static ParameterValue of(const char* s) { return of(std::string(s)); }
  static ParameterValue list(std::vector<ParameterValue> items);
};

// The range of a number or an integer (always finite besides).
struct Bounds {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;

  bool contains(double x) const;
  // "a finite number in [0, 1]", "an integer >= 8", ...; `what` names the type.
  std::string text(const std::string& what) const;
};
Bounds at_least(double lo);                // [lo, inf)
Bounds above(double lo);                   // (lo, inf)
Bounds between(double lo, double hi);      // [lo, hi]
Bounds above_up_to(double lo, double hi);  // (lo, hi]

// What a parameter may be beyond its type.
struct Allowed {
  Bounds bounds;                                    // numbers, integers (and their lists)
  std::function<std::vector<std::string>()> names;  // strings (and their lists): one of these
  std::string text;                                 // shown instead of the generated text, if set
};
inline Allowed allowed(Bounds b) { return Allowed{b, {}, {}}; }
inline Allowed described(std::string text) { return Allowed{{}, {}, std::move(text)}; }
inline Allowed one_of(std::function<std::vector<std::string>()> names) {
  return Allowed{{}, std::move(names), {}};
}

// How each type is read, checked, written back and described (parameter_types.hpp).
template <class T>
struct ParameterType;

// What a user reads about one parameter.
struct ParameterInfo {
  std::string table;                     // "particles"
  std::string key;                       // "r"
  std::string kind;                      // "number", "integer", "string", "boolean", "list of numbers", ...
  std::string unit;                      // "length/time", "1" for a pure number, "" for none
  std::string doc;                       // one line: meaning
  std::function<std::string()> allowed;  // what is allowed, as error messages say it
  std::string dotted() const { return table + "." + key; }
};

// The declarations of one scene table, over the struct Params that holds it.
template <class Params>
class ParameterTable {
 public:
  struct Entry {
    ParameterInfo info;
    std::function<void(Params&, const ParameterValue&)> set;  // reads and checks; InputError
    std::function<ParameterValue(const Params&)> get;
    std::function<void(const Params&)> check;  // the rule on the current value; InputError
  };

  explicit ParameterTable(std::string table) : table_(std::move(table)) {}

  template <class T>
  ParameterTable& add(T Params::*member, std::string key, std::string unit, std::string doc,
                      Allowed rule = {});

  const std::string& name() const { return table_; }
  const std::vector<Entry>& entries() const { return entries_; }
  // The entry of `key`; InputError naming table.key and listing the keys if none.
  const Entry& entry(const std::string& key, const std::string& written = "") const;
  // Sets one key from a value (reader's view); InputError as Entry::set.
  void set(Params& p, const std::string& key, const ParameterValue& value) const { entry(key).set(p, value); }
  // Checks every declared rule (for parameters built in code); InputError on the first failure.
  void check(const Params& p) const {
    for (const Entry& e : entries_) e.check(p);
  }
  // "r, delta, ..." in declaration order.
  std::string keys_text() const;

 private:
  std::string table_;
  std::vector<Entry> entries_;
};

}  // namespace shockgas

#include "shockgas/core/parameter_types.hpp"

namespace shockgas {

template <class Params>
template <class T>
ParameterTable<Params>& ParameterTable<Params>::add(T Params::*member, std::string key, std::string unit,
                                                    std::string doc, Allowed rule) {
  using Type = ParameterType<T>;
  Entry e;
  e.info = ParameterInfo{table_,          std::move(key), Type::kind(),
                         std::move(unit), std::move(doc), [rule] { return Type::allowed_text(rule); }};
  const std::string dotted = e.info.dotted();
  e.set = [member, dotted, rule](Params& p, const ParameterValue& v) {
    p.*member = Type::read(v, dotted, rule);
  };
  e.get = [member](const Params& p) { return Type::write(p.*member); };
  e.check = [member, dotted, rule](const Params& p) { Type::check(p.*member, dotted, rule); };
  entries_.push_back(std::move(e));
  return *this;
}

template <class Params>
const typename ParameterTable<Params>::Entry& ParameterTable<Params>::entry(
    const std::string& key, const std::string& written) const {
  for (const Entry& e : entries_)
    if (e.info.key == key) return e;
  throw InputError(table_ + "." + key, written.empty() ? "(any value)" : written,
                   "a key of [" + table_ + "]: " + keys_text());
}

template <class Params>
std::string ParameterTable<Params>::keys_text() const {
  std::string list;
  for (const Entry& e : entries_) list += (list.empty() ? "" : ", ") + e.info.key;
  return list;
}

}  // namespace shockgas
