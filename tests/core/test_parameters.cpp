// Declared parameters (shockgas/core/parameters.hpp): reading, checking and describing a
// member through its one declaration.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "shockgas/core/error.hpp"
#include "shockgas/core/parameters.hpp"

namespace shockgas {
namespace {

enum class Colour { red, green };
constexpr std::array<EnumName<Colour>, 3> enum_names(Colour) {
  return {{{Colour::red, "red"}, {Colour::green, "green"}, {Colour::green, "verde"}}};
}

struct Example {
  double x = 0.5;
  std::size_t n = 4;
  bool flag = false;
  std::string name = "a";
  Colour colour = Colour::red;
  std::vector<double> times = {};
};

ParameterTable<Example> table() {
  ParameterTable<Example> t("example");
  t.add(&Example::x, "x", "length", "a length", allowed(between(0, 1)));
  t.add(&Example::n, "n", "1", "a count", allowed(at_least(2)));
  t.add(&Example::flag, "flag", "", "a switch");
  t.add(&Example::name, "name", "", "one of two", one_of([] { return std::vector<std::string>{"a", "b"}; }));
  t.add(&Example::colour, "colour", "", "a colour");
  t.add(&Example::times, "times", "time", "some times", allowed(above(0)));
  return t;
}

InputError error_of(const std::string& key, const ParameterValue& v) {
  Example e;
  try {
    table().set(e, key, v);
  } catch (const InputError& err) {
    return err;
  }
  ADD_FAILURE() << key << " = " << v.written << " accepted";
  return InputError("", "", "");
}

TEST(Parameters, DeclarationSetsTheMemberAndDescribesIt) {
  Example e;
  const auto t = table();
  t.set(e, "x", ParameterValue::of(0.25));
  t.set(e, "n", ParameterValue::of(std::int64_t{7}));
  t.set(e, "colour", ParameterValue::of("verde"));  // an alias
  t.set(e, "times", ParameterValue::of(2.0));       // a single value is a list of one
  EXPECT_EQ(e.x, 0.25);
  EXPECT_EQ(e.n, 7u);
  EXPECT_EQ(e.colour, Colour::green);
  EXPECT_EQ(e.times, std::vector<double>{2.0});
  EXPECT_EQ(t.entry("colour").get(e).text, "green");  // printed by its first name
  EXPECT_EQ(t.entry("x").info.dotted(), "example.x");
  EXPECT_EQ(t.entry("x").info.allowed(), "a finite number in [0, 1]");
  EXPECT_EQ(t.entry("n").info.allowed(), "an integer >= 2");
  EXPECT_EQ(t.entry("colour").info.allowed(), "\"red\", \"green\" or \"verde\"");
  EXPECT_EQ(t.entry("name").info.allowed(), "one of \"a\" or \"b\"");
  EXPECT_EQ(t.entry("times").info.kind, "list of numbers");
}

TEST(Parameters, BadValuesNameTheKeyTheValueAndWhatIsAllowed) {
  const auto range = error_of("x", ParameterValue::of(1.5));
  EXPECT_EQ(range.key(), "example.x");
  EXPECT_EQ(range.value(), "1.5");
  EXPECT_EQ(range.allowed(), "a finite number in [0, 1]");
  EXPECT_EQ(error_of("x", ParameterValue::of("wide")).key(), "example.x");
  EXPECT_EQ(error_of("n", ParameterValue::of(2.5)).allowed(), "an integer >= 2");
  EXPECT_EQ(error_of("n", ParameterValue::of(std::int64_t{-5})).allowed(), "an integer >= 2");
  EXPECT_EQ(error_of("flag", ParameterValue::of(std::int64_t{1})).key(), "example.flag");
  EXPECT_EQ(error_of("name", ParameterValue::of("c")).allowed(), "one of \"a\" or \"b\"");
  EXPECT_EQ(error_of("colour", ParameterValue::of("blue")).key(), "example.colour");
  EXPECT_EQ(
      error_of("times", ParameterValue::list({ParameterValue::of(1.0), ParameterValue::of(-1.0)})).value(),
      "-1");
  const auto unknown = error_of("y", ParameterValue::of(1.0));
  EXPECT_EQ(unknown.key(), "example.y");
  EXPECT_NE(unknown.allowed().find("x, n, flag, name, colour, times"), std::string::npos);
}

TEST(Parameters, WholeFloatsAreIntegers) {
  Example e;
  table().set(e, "n", ParameterValue::of(1e6));
  EXPECT_EQ(e.n, 1000000u);
}

TEST(Parameters, CheckAppliesTheRulesToValuesSetInCode) {
  Example e;
  EXPECT_NO_THROW(table().check(e));
  e.x = 2;
  try {
    table().check(e);
    FAIL() << "x = 2 passed";
  } catch (const InputError& err) {
    EXPECT_EQ(err.key(), "example.x");
    EXPECT_EQ(err.value(), "2");
  }
}

TEST(EnumNames, NamesAreDeclaredOnce) {
  EXPECT_EQ(name_of(Colour::green), "green");
  EXPECT_EQ(parse_enum<Colour>("red", "k"), Colour::red);
  EXPECT_THROW(parse_enum<Colour>("blue", "k"), InputError);
  EXPECT_EQ(choices_text({"a"}), "\"a\"");
}

}  // namespace
}  // namespace shockgas
