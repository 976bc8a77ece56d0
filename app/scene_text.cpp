// Scenes as text: the commented default scene and the resolved parameters,
// both printed from the key registration.
#include <sstream>

#include "scene_schema.hpp"
#include "shockgas/app/scene.hpp"

namespace shockgas::app {

namespace {

std::string comment(const KeySpec& spec) {
  std::string c = "# " + spec.doc;
  if (!spec.unit.empty() && spec.unit != "1") c += " [" + spec.unit + "]";
  return c + ". Allowed: " + spec.allowed + ".";
}

// A table whose presence changes what runs ([sweep]) is printed commented out
// unless the scene has it, so that the printed text runs what the scene runs.
std::string print_tables(const Scene& scene, bool with_comments) {
  std::ostringstream out;
  for (const auto& table : scene_tables()) {
    const std::string off = table.name == "sweep" && !scene.has_sweep ? "# " : "";
    if (with_comments) out << "\n# " << table.doc << "\n";
    out << off << "[" << table.name << "]\n";
    for (const auto& spec : scene_schema()) {
      if (spec.table != table.name) continue;
      if (with_comments) out << comment(spec) << "\n";
      out << off << spec.key << " = " << spec.print(scene) << "\n";
    }
    if (!with_comments) out << "\n";
  }
  return out.str();
}

}  // namespace

std::string default_scene_text() {
  Scene defaults;
  std::ostringstream out;
  out << "# shockgas scene: every key with its default, unit and allowed range.\n"
         "# A table that is present runs that part: without [particles] no particles run,\n"
         "# without [continuum] no solver, without [compare] no comparison.\n"
         "# Any key can be overridden on the command line: --set particles.r=0.5\n"
      << print_tables(defaults, true);
  return out.str();
}

std::string resolved_scene_text(const Scene& scene) { return print_tables(scene, false); }

}  // namespace shockgas::app
