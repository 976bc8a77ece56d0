#pragma once
// The registration of every scene key: its table, type, unit, allowed range,
// documentation, and how to read and print it. The parser, the commented
// default scene (`shockgas scene --defaults`) and the resolved-parameter dump
// all come from this one list, so they cannot drift apart.
#include <toml++/toml.h>

#include <functional>
#include <string>
#include <vector>

#include "shockgas/app/scene.hpp"

namespace shockgas::app {

struct KeySpec {
  std::string table;    // "particles"
  std::string key;      // "r"
  std::string kind;     // "number", "integer", "string", "boolean", "list of numbers", "list of strings"
  std::string unit;     // "length/time", "1", "" for none
  std::string allowed;  // human-readable allowed range, as in error messages
  std::string doc;      // one line: meaning
  std::function<void(const toml::node&, Scene&)> read;  // throws InputError on a wrong type
  std::function<std::string(const Scene&)> print;       // TOML text of the value

  std::string dotted() const { return table + "." + key; }
};

// Every key, table by table, in the order of the default scene.
const std::vector<KeySpec>& scene_schema();

// The tables, in order, each with a one-line description.
struct TableSpec {
  std::string name, doc;
};
const std::vector<TableSpec>& scene_tables();

// TOML text of a node (for error messages).
std::string node_text(const toml::node& node);

}  // namespace shockgas::app
