// Scene text -> Scene: TOML parsing, --set overrides, strict key checking and
// validation, every error located at file:line (or at the --set that caused it).
#include "shockgas/app/input/scene_parser.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "shockgas/app/files/file_problem.hpp"
#include "shockgas/app/output/frames.hpp"
#include "shockgas/app/output/output_layout.hpp"
#include "shockgas/app/scene/scene.hpp"
#include "shockgas/app/scene/scene_schema.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

std::string location(const std::string& path, const toml::node& node) {
  return path + ":" + std::to_string(node.source().begin.line);
}

std::string table_names() {
  std::string list;
  for (const auto& t : scene_schema()) list += (list.empty() ? "[" : ", [") + t.name + "]";
  return list;
}

// An override and where it was given: "--set particles.r=0.5", or a variant of
// [sweep] ("scene.toml:30 (sweep variant 2: particles.r=0.5)").
struct Override {
  std::string assignment;
  std::string origin;
};

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t");
  return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

bool has_control_character(const std::string& s) {
  return std::any_of(s.begin(), s.end(),
                     [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}

// The value of an override: one TOML value, or a bare word that is not TOML
// (a string). Anything after the value (a line break and another key: the
// TOML reader would take both) is refused, not dropped.
toml::table override_value(const std::string& text, const Override& o) {
  const std::string allowed =
      "table.key=value with one TOML value (e.g. particles.r=0.5); this one holds more after its value";
  try {
    toml::table parsed = toml::parse("value = " + text);
    if (parsed.size() != 1) throw InputError("--set", to_text(o.assignment), allowed, o.origin);
    return parsed;
  } catch (const toml::parse_error&) {
    if (has_control_character(text)) throw InputError("--set", to_text(o.assignment), allowed, o.origin);
    toml::table word;
    word.insert_or_assign("value", text);
    return word;
  }
}

// "particles.r=0.5" (spaces around '=' allowed): one key, its value read as a
// TOML value; a bare word that is not TOML is a string.
void apply_override(toml::table& root, const Override& o, Scene& scene) {
  const std::string& assignment = o.assignment;
  const auto eq = assignment.find('=');
  const std::string key = trimmed(assignment.substr(0, eq));
  const auto dot = key.find('.');
  if (eq == std::string::npos || dot == std::string::npos || dot == 0 || dot + 1 == key.size() ||
      has_control_character(key))
    throw InputError("--set", to_text(assignment), "table.key=value, e.g. particles.r=0.5", o.origin);
  const std::string table = key.substr(0, dot), name = key.substr(dot + 1);
  const std::string text = trimmed(assignment.substr(eq + 1));
  toml::table parsed = override_value(text, o);
  if (!root.contains(table)) {
    root.insert_or_assign(table, toml::table{});
    scene.key_origin[table] = o.origin;
  }
  auto* tbl = root[table].as_table();
  if (!tbl) throw InputError(table, "(not a table)", "a table " + table_names(), o.origin);
  tbl->insert_or_assign(name, *parsed["value"].node());
  scene.key_origin[key] = o.origin;
}

void read_table(const TableSpec& table, const toml::table& tbl, const std::string& path, Scene& scene) {
  for (const auto& [k, node] : tbl) {
    const std::string key(k.str());
    const std::string dotted = table.name + "." + key;
    const auto origin = scene.key_origin.count(dotted) ? scene.key_origin[dotted] : location(path, node);
    const KeySpec* spec = table.find(key);
    if (!spec)
      throw InputError(dotted, node_text(node), "a key of [" + table.name + "]: " + table.keys_text(),
                       origin);
    try {
      spec->set(scene, from_toml(node));
    } catch (const InputError& e) {
      throw e.located(origin);
    }
    scene.key_origin[dotted] = origin;
  }
}

// A top-level name that is not one of the tables: a table of the file, a key
// outside any table, or the table of an override.
[[noreturn]] void refuse_table(const std::string& table, const toml::node& node, const std::string& path,
                               const Scene& scene) {
  const std::string allowed = "the tables " + table_names() + " (keys go inside a table)";
  const auto set = scene.key_origin.find(table);
  if (set != scene.key_origin.end() && node.is_table() && !node.as_table()->empty()) {
    const auto first = node.as_table()->begin();
    throw InputError(table + "." + std::string(first->first.str()), node_text(first->second),
                     "a key of one of " + allowed, set->second);
  }
  throw InputError(table, node.is_table() ? "[" + table + "]" : node_text(node), allowed,
                   location(path, node));
}

void read_tables(const toml::table& root, const std::string& path, Scene& scene) {
  for (const auto& [k, node] : root) {
    const std::string table(k.str());
    const TableSpec* spec = find_table(table);
    if (!spec || !node.is_table()) refuse_table(table, node, path, scene);
    read_table(*spec, *node.as_table(), path, scene);
  }
  scene.has_particles = root.contains("particles");
  scene.has_continuum = root.contains("continuum");
  scene.has_compare = root.contains("compare");
  scene.has_statistics = root.contains("statistics");
  scene.has_sweep = root.contains("sweep");
}

// A relative initial.file written in a scene file is relative to that file.
void resolve_file(Scene& scene, const std::string& path) {
  auto& file = scene.initial.file;
  if (file.empty() || std::filesystem::path(file).is_absolute()) return;
  const auto origin = scene.key_origin["initial.file"];
  if (origin.rfind("--set", 0) == 0) return;
  const auto dir = std::filesystem::path(path).parent_path();
  file = (dir / file).lexically_normal().string();
}

void validate_sweep(const SweepParams& s) {
  require(!s.variants.empty(), "sweep.variants", std::string("[]"), "at least one variant");
  require(s.labels.empty() || s.labels.size() == s.variants.size(), "sweep.labels", s.labels.size(),
          "one label per variant (" + std::to_string(s.variants.size()) + "), or none");
  for (std::size_t i = 0; i < s.labels.size(); ++i)  // each names its variant's rows and plots
    require(std::find(s.labels.begin(), s.labels.begin() + static_cast<std::ptrdiff_t>(i), s.labels[i]) ==
                s.labels.begin() + static_cast<std::ptrdiff_t>(i),
            "sweep.labels", s.labels[i], "distinct labels");
  require(s.reference_values.empty() || s.reference_values.size() == s.variants.size(),
          "sweep.reference_values", s.reference_values.size(),
          "one value per variant (" + std::to_string(s.variants.size()) + "), or none");
  require(s.reference_key.empty() || find_in_layout(LayoutEntry::Kind::summary, s.reference_key),
          "sweep.reference_key", s.reference_key,
          "a key of summary.json (docs/output.md), e.g. analysis.T_exponent");
}

// "a=1; b=2" -> {"a=1", "b=2"}
std::vector<std::string> split_assignments(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ';')) {
    const auto first = item.find_first_not_of(" \t"), last = item.find_last_not_of(" \t");
    if (first != std::string::npos) out.push_back(item.substr(first, last - first + 1));
  }
  return out;
}

// [compare] configures the particle analysis (cooling law, velocity
// distribution); with [continuum] present it also compares the two models, which
// needs both at one time, on the ring, and the solver it names.
void validate_compare(const Scene& scene) {
  require(scene.has_particles, "compare", std::string("(table)"), "[compare] only together with [particles]");
  require(scene.compare.min_cluster_particles <= static_cast<double>(scene.initial.N),
          "compare.min_cluster_particles", scene.compare.min_cluster_particles,
          "0 (automatic) or at most initial.N = " + std::to_string(scene.initial.N) +
              ": a cluster holds at most every particle");
  if (!scene.has_continuum) return;
  const auto& solvers = scene.continuum.solvers;
  require(std::find(solvers.begin(), solvers.end(), scene.compare.solver) != solvers.end(), "compare.solver",
          scene.compare.solver, "one of continuum.solvers");
  // The shocks' masses come from the density (found: hopf_cole, velocity only,
  // was accepted and reported 0 shocks matched with an error of 0).
  require(continuum::solver_info(scene.compare.solver).density, "compare.solver", scene.compare.solver,
          "a solver of continuum.solvers that gives the density (the shocks' masses)");
  require(scene.continuum.t_end == 0 || scene.continuum.t_end == scene.particles.t_end, "continuum.t_end",
          scene.continuum.t_end, "0 or particles.t_end when [compare] is present (both at one time)");
  require(scene.particles.geometry == particles::Geometry::ring &&
              scene.continuum.boundary == continuum::Boundary::periodic,
          "particles.geometry", name_of(scene.particles.geometry),
          "\"" + name_of(particles::Geometry::ring) + "\" with continuum.boundary = \"" +
              name_of(continuum::Boundary::periodic) + "\" when [compare] is present");
  require(scene.initial.velocities != Velocities::expression, "initial.velocities",
          name_of(scene.initial.velocities),
          "particle data (not \"" + name_of(Velocities::expression) + "\") when [compare] is present");
}

// [statistics] reduces each realization's final clusters: it needs the
// particles, recording them.
void validate_statistics(const Scene& scene) {
  require(scene.has_particles, "statistics", std::string("(table)"),
          "[statistics] only together with [particles]");
  const particles::ParticleParams& p = scene.particles;
  require(particles::records_final_clusters(p, scene.initial.N), "particles.final_clusters",
          name_of(p.final_clusters),
          "\"always\", or \"auto\" while " + particles::final_clusters_auto_rule() +
              " (here N = " + std::to_string(scene.initial.N) + ", N x realizations = " +
              to_text(static_cast<double>(scene.initial.N) * static_cast<double>(p.realizations), 7) +
              "), when [statistics] is present: it reduces each realization's final clusters");
}

// The name becomes a directory, out/<name>/: a name, not a path.
void validate_name(const Scene& scene) {
  const std::string& n = scene.name;
  bool ok = !n.empty() && n.size() <= 200 && n.front() != '.';
  for (unsigned char c : n) ok = ok && c != '/' && c != '\\' && c >= 0x20 && c != 0x7f;
  const bool from_file = !scene.key_origin.count("scene.name");
  require(ok, "scene.name", n,
          kSceneNameRule + (from_file ? " (this one is the file's name: set [scene] name)" : ""));
}

void validate_scene(const Scene& scene) {
  validate_name(scene);
  validate(scene.initial);
  particles::validate(scene.particles);
  continuum::validate(scene.continuum);
  compare::validate(scene.compare);
  if (scene.has_sweep) validate_sweep(scene.sweep);
  if (scene.has_continuum && !scene.has_particles)
    require(scene.continuum.t_end > 0, "continuum.t_end", scene.continuum.t_end,
            "a time > 0 (a scene without [particles] must give continuum.t_end)");
  if (scene.has_compare) validate_compare(scene);
  if (scene.has_statistics) validate_statistics(scene);
  check_animation(scene);
}

Scene parse(const std::string& text, const std::string& path, const std::vector<Override>& overrides) {
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    throw FileProblem("SCENE", path + ":" + std::to_string(at.line) + ":" + std::to_string(at.column),
                      "TOML syntax error", std::string(e.description()));
  }
  Scene scene;
  scene.path = path;
  scene.text = text;
  for (const auto& o : overrides) {
    apply_override(root, o, scene);
    scene.overrides.push_back(o.assignment);
  }
  read_tables(root, path, scene);
  if (!scene.has_particles && !scene.has_continuum)
    throw FileProblem("SCENE", path, "runs nothing", "a scene needs [particles] or [continuum]");
  if (scene.name.empty()) scene.name = std::filesystem::path(path).stem().string();
  resolve_file(scene, path);
  scene.solver_note = particles::solver_choice_note(scene.particles);
  scene.particles.solver = particles::chosen_solver(scene.particles);
  try {
    validate_scene(scene);
  } catch (const InputError& e) {
    const auto it = scene.key_origin.find(e.key());
    throw e.located(it != scene.key_origin.end() ? it->second : path);
  }
  return scene;
}

std::vector<Override> command_line(const std::vector<std::string>& overrides) {
  std::vector<Override> out;
  for (const auto& o : overrides) out.push_back({o, "--set " + printable(o)});
  return out;
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& path,
                  const std::vector<std::string>& overrides) {
  return parse(text, path, command_line(overrides));
}

std::vector<Scene> expand_sweep(const Scene& scene) {
  std::vector<Scene> variants;
  const std::string at =
      scene.key_origin.count("sweep.variants") ? scene.key_origin.at("sweep.variants") : scene.path;
  for (std::size_t i = 0; i < scene.sweep.variants.size(); ++i) {
    const std::string variant = "sweep variant " + std::to_string(i + 1) + ": " + scene.sweep.variants[i];
    auto overrides = command_line(scene.overrides);
    for (const auto& a : split_assignments(scene.sweep.variants[i])) {
      require(a.rfind("sweep.", 0) != 0 && a.rfind("scene.", 0) != 0, "sweep.variants", a,
              "overrides of keys outside [sweep] and [scene] (a variant's name is its label)");
      overrides.push_back({a, at + " (" + variant + ")"});
    }
    Scene v;
    try {
      v = parse(scene.text, scene.path, overrides);
    } catch (const InputError& e) {
      if (e.where().find("(sweep variant") != std::string::npos) throw;
      throw InputError(e.key(), e.value(), e.allowed(), e.where() + " (" + variant + ")");
    }
    v.has_sweep = false;
    const std::string label = scene.sweep.labels.empty() ? scene.sweep.variants[i] : scene.sweep.labels[i];
    v.name = scene.name + "/" + label;
    variants.push_back(std::move(v));
  }
  return variants;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (status.type() == std::filesystem::file_type::not_found)
    throw FileProblem("SCENE", path, "no such file", "");
  if (status.type() == std::filesystem::file_type::directory)
    throw FileProblem("SCENE", path, "a directory",
                      "give a scene file (.toml), e.g. data/scenes/default.toml");
  if (status.type() != std::filesystem::file_type::regular)
    throw FileProblem("SCENE", path, "not a regular file", "give a scene file (.toml)");
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw FileProblem("SCENE", path, "unreadable", "");
  if (text.str().find_first_not_of(" \t\r\n") == std::string::npos)
    throw FileProblem("SCENE", path, "empty", "a scene needs [particles] or [continuum]");
  return parse_scene(text.str(), path, overrides);
}

}  // namespace shockgas::app
