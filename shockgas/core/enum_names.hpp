#pragma once
// The names of an enum's values as scenes, summaries and messages spell them,
// declared once beside the enum as a constexpr function found by argument-
// dependent lookup:
//
//   enum class Geometry { ring, line };
//   constexpr std::array<EnumName<Geometry>, 2> enum_names(Geometry) {
//     return {{{Geometry::ring, "ring"}, {Geometry::line, "line"}}};
//   }
//
// Then name_of(Geometry::line) == "line", parse_enum<Geometry>("ring", key) ==
// Geometry::ring, and a scene key of type Geometry accepts exactly these names
// (shockgas/core/parameters.hpp). A value may carry a second spelling (an alias) in a
// later entry: it is accepted, and the first spelling is the one printed.
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "shockgas/core/error.hpp"

namespace shockgas {

template <class E>
struct EnumName {
  E value;
  const char* name;
};

template <class E>
concept NamedEnum = std::is_enum_v<E> && requires(E e) {
  enum_names(e);
};

// The first name declared for value.
template <NamedEnum E>
std::string name_of(E value) {
  for (const auto& entry : enum_names(E{}))
    if (entry.value == value) return entry.name;
  return "(unnamed value " + std::to_string(static_cast<long long>(value)) + ")";
}

// Every accepted spelling, in declaration order.
template <NamedEnum E>
std::vector<std::string> enum_choices() {
  std::vector<std::string> names;
  for (const auto& entry : enum_names(E{})) names.emplace_back(entry.name);
  return names;
}

// "\"a\"", "\"a\" or \"b\"", "\"a\", \"b\" or \"c\"": the choices as messages list them.
std::string choices_text(const std::vector<std::string>& names);

// The value named `text`; InputError(key, text, the choices) if none is.
template <NamedEnum E>
E parse_enum(std::string_view text, const std::string& key) {
  for (const auto& entry : enum_names(E{}))
    if (text == entry.name) return entry.value;
  throw InputError(key, to_text(std::string(text)), choices_text(enum_choices<E>()));
}

}  // namespace shockgas
