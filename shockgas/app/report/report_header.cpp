// The head of report.md: what was asked and what was run. The scene's
// description is its author's text and may name values that an override has
// changed, so the run is also described from the parameters themselves: every
// key the scene file or a --set gave, with the value used (scene_schema.hpp),
// and the overrides as given.
#include <sstream>

#include "shockgas/app/report/report.hpp"
#include "shockgas/app/scene/scene_schema.hpp"

namespace shockgas::app {

namespace {

// The tables that hold the physics and numerics of a run, if the scene has them.
bool describes_the_run(const Scene& scene, const std::string& table) {
  if (table == "initial") return true;
  if (table == "particles") return scene.has_particles;
  if (table == "continuum") return scene.has_continuum;
  if (table == "compare") return scene.has_compare;
  return false;  // [scene], [sweep], [output]: what the run is called and what it writes
}

bool is_override(const std::string& origin) { return origin.rfind("--set", 0) == 0; }

std::string parameters_set(const Scene& scene) {
  std::string list;
  for (const auto& table : scene_schema()) {
    if (!describes_the_run(scene, table.name)) continue;
    for (const auto& key : table.keys) {
      const auto it = scene.key_origin.find(table.name + "." + key.info.key);
      if (it == scene.key_origin.end()) continue;
      list += (list.empty() ? "" : ", ") + std::string("`") + it->first + " = " + toml_text(key.get(scene)) +
              "`" + (is_override(it->second) ? " (override)" : "");
    }
  }
  return list.empty() ? "none (every key at its default)" : list;
}

std::string overrides(const Scene& scene) {
  if (scene.overrides.empty()) return "none";
  std::string list;
  for (const auto& o : scene.overrides) list += (list.empty() ? "" : " ") + std::string("`--set ") + o + "`";
  return list;
}

}  // namespace

std::string report_header(const Scene& scene) {
  std::ostringstream out;
  out << "# shockgas report: " << scene.name << "\n\n";
  if (!scene.description.empty())
    out << "Scene description, as written" << (scene.overrides.empty() ? "" : " (before the overrides below)")
        << ": " << scene.description << "\n\n";
  out << "Run as made, from `" << scene.path << "` with overrides: " << overrides(scene)
      << ". Parameters set by the scene and the overrides (every other key at its default; all of them in "
         "result.h5, attribute `resolved_parameters`): "
      << parameters_set(scene) << ".\n\n";
  return out.str();
}

}  // namespace shockgas::app
