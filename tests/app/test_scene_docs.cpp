// The scene keys as documented: docs/scenes.md and `shockgas scene --defaults`
// come from the declarations, and every declared key refuses a bad value with
// its own name and the place it was written.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/scene/scene.hpp"
#include "shockgas/app/scene/scene_schema.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SceneDocs, ScenesMarkdownIsGeneratedFromTheDeclarations) {
  const std::string doc = read_file(std::string(SHOCKGAS_SOURCE_DIR) + "/docs/scenes.md");
  EXPECT_EQ(doc, scene_reference_markdown())
      << "docs/scenes.md differs from the declarations: regenerate it with\n"
         "  build/shockgas scene --markdown > docs/scenes.md";
}

TEST(SceneDocs, EveryKeyIsInTheDefaultSceneWithItsUnitAndAllowedValues) {
  const std::string text = default_scene_text();
  for (const auto& table : scene_schema())
    for (const auto& key : table.keys) {
      // [sweep] is printed commented out: its presence would make the scene a sweep.
      const std::string line = (table.name == "sweep" ? "\n# " : "\n") + key.info.key + " = ";
      EXPECT_NE(text.find(line), std::string::npos) << key.info.dotted();
      EXPECT_NE(text.find("Allowed: " + key.info.allowed() + "."), std::string::npos) << key.info.dotted();
      EXPECT_FALSE(key.info.doc.empty()) << key.info.dotted();
    }
}

// A value of the wrong type for every key (free text and booleans can only be
// wrong in type), one outside the range for numbers and integers, a fraction for
// integers and an unknown name for choices.
std::vector<std::string> bad_values(const KeySpec& key, const Scene& defaults) {
  const ParameterValue v = key.get(defaults);
  using Type = ParameterValue::Type;
  const bool text = v.type == Type::text || (v.type == Type::list && key.info.kind == "list of strings");
  std::vector<std::string> bad = {text ? "1.5" : "\"not a " + key.info.kind + "\""};
  if (key.info.kind == "number" || key.info.kind == "integer") bad.push_back("-1e300");
  if (key.info.kind == "integer") bad.push_back("2.5");
  const std::string allowed = key.info.allowed();
  for (const char* choices : {"\" or \"", "one of \"", "a list from \""})
    if (allowed.find(choices) != std::string::npos) {
      bad.push_back("\"no-such-choice\"");
      break;
    }
  return bad;
}

TEST(SceneDocs, EveryKeyRefusesABadValueNamingItselfAndItsLine) {
  const Scene defaults;
  int checked = 0;
  for (const auto& table : scene_schema())
    for (const auto& key : table.keys)
      for (const std::string& value : bad_values(key, defaults)) {
        const std::string scene = "[" + table.name + "]\n" + key.info.key + " = " + value + "\n";
        try {
          parse_scene(scene, "bad.toml");
          ADD_FAILURE() << key.info.dotted() << " = " << value << " accepted";
        } catch (const InputError& e) {
          EXPECT_EQ(e.key(), key.info.dotted()) << value << ": " << e.what();
          EXPECT_EQ(e.where(), "bad.toml:2") << key.info.dotted() << " = " << value << ": " << e.what();
          EXPECT_EQ(std::string(e.what()).rfind("bad.toml:2: " + key.info.dotted() + " = ", 0), 0u)
              << e.what();
          ++checked;
        }
      }
  EXPECT_GT(checked, 60);
}

TEST(SceneDocs, IntegerKeysTakeWholeFloatsAndRefuseFractions) {
  const Scene s = parse_scene("[particles]\nsamples = 4e1\nrealizations = 2.0\n", "s.toml");
  EXPECT_EQ(s.particles.samples, 40u);
  EXPECT_EQ(s.particles.realizations, 2u);
  for (const char* bad : {"2.5", "1e-3", "-4", "inf"}) {
    try {
      parse_scene(std::string("[particles]\nsamples = ") + bad + "\n", "s.toml");
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "particles.samples");
      EXPECT_NE(e.allowed().find("an integer >= 1"), std::string::npos) << e.what();
    }
  }
}

TEST(SceneDocs, ComparisonKeysAreNamedAsTheSceneWritesThem) {
  for (const char* key : {"match_distance", "min_cluster_particles", "cluster_gap", "cluster_dv"}) {
    try {
      parse_scene(std::string("[particles]\n[compare]\n") + key + " = -1\n", "scene.toml");
      ADD_FAILURE() << key << " = -1 accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), std::string("scene.toml:3: compare.") + key +
                                           " = -1 is not allowed; allowed: a finite number >= 0");
    }
  }
}

}  // namespace
}  // namespace shockgas::app
