#pragma once
// Every scene key, table by table: the declarations of each part
// (initial_parameters(), particles::parameters(), continuum::parameters(),
// compare::parameters()) and of the scene's own tables ([scene], [sweep],
// [output]), bound to the Scene that holds them. The parser, the commented
// default scene (`shockgas scene --defaults`), the resolved-parameter dump and
// docs/scenes.md all come from this one list, so they cannot drift apart.
#include <toml++/toml.h>

#include <functional>
#include <string>
#include <vector>

#include "shockgas/app/scene/scene.hpp"
#include "shockgas/core/parameters.hpp"

namespace shockgas::app {

struct KeySpec {
  ParameterInfo info;
  std::function<void(Scene&, const ParameterValue&)> set;  // throws InputError naming table.key
  std::function<ParameterValue(const Scene&)> get;
};

struct TableSpec {
  std::string name;           // "particles"
  std::string doc;            // one line: what the table is, and what its presence runs
  std::vector<KeySpec> keys;  // in declaration order
  const KeySpec* find(const std::string& key) const;
  std::string keys_text() const;  // "r, delta, ..."
};

// The tables, in the order of the default scene.
const std::vector<TableSpec>& scene_schema();
const TableSpec* find_table(const std::string& name);

// A TOML node as a ParameterValue (written = its TOML text), and back.
ParameterValue from_toml(const toml::node& node);
std::string toml_text(const ParameterValue& value);

// What [scene] name may be: it names the directory out/<name>/, so it is a
// name, not a path.
inline const std::string kSceneNameRule =
    "a name, not a path: no '/', '\\' or control characters, not starting with '.', at most 200 bytes";

// TOML text of a node (for error messages; a long one is cut).
std::string node_text(const toml::node& node);

}  // namespace shockgas::app
