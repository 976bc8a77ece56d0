#pragma once
// Reading a scene: a TOML file or text, the --set overrides applied to it, every
// key checked against its declaration (scene/scene_schema.hpp) and every rule
// between keys, each error located at file:line or at the --set that caused it.
#include <string>
#include <vector>

#include "shockgas/app/scene/scene.hpp"

namespace shockgas::app {

// Reads, overrides and validates a scene; throws InputError (located at
// file:line) on an unknown key, a wrong type or a value out of range. No work
// is done and nothing is written before this returns.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

// Parses scene text (path used only in messages).
Scene parse_scene(const std::string& text, const std::string& path,
                  const std::vector<std::string>& overrides = {});

// The variants of a [sweep] scene, each parsed and validated as a scene of its
// own (name "<scene>/<label>"); throws InputError before any work.
std::vector<Scene> expand_sweep(const Scene& scene);

}  // namespace shockgas::app
