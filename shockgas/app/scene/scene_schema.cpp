#include "shockgas/app/scene/scene_schema.hpp"

#include <cmath>
#include <sstream>

#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

ParameterTable<Scene> scene_table() {
  ParameterTable<Scene> t("scene");
  t.add(&Scene::name, "name", "", "scene name; results go to out/<name>/",
        described(kSceneNameRule + "; empty = the file's name"));
  t.add(&Scene::description, "description", "", "what the scene shows");
  t.add(&Scene::expected_runtime, "expected_runtime", "", "wall time on a 2-core machine");
  return t;
}

ParameterTable<SweepParams> sweep_table() {
  using P = SweepParams;
  ParameterTable<P> t("sweep");
  t.add(&P::variants, "variants", "", "run the scene once per variant, side by side",
        described("overrides \"table.key=value; ...\" per variant"));
  t.add(&P::labels, "labels", "", "variant labels for tables and plots",
        described("one label per variant, or empty"));
  t.add(&P::reference_key, "reference_key", "", "the result compared with reference_values in the report",
        described("a summary.json key, or empty"));
  t.add(&P::reference_values, "reference_values", "", "published values of reference_key",
        described("one text per variant (\"\" for none), or empty"));
  t.add(&P::reference_source, "reference_source", "", "where the reference values come from");
  return t;
}

ParameterTable<OutputParams> output_table() {
  using P = OutputParams;
  ParameterTable<P> t("output");
  t.add(&P::plots, "plots", "", "make PNG plots (and the animation's movie when animation = true)");
  t.add(&P::fields, "fields", "", "store the continuum fields in result.h5");
  t.add(&P::initial, "initial", "",
        "store realization 0's initial bodies (/initial/x, v, m): always, never, or auto (at most " +
            to_text(kStoredStateBodies) + " bodies; the scene and its seed draw them again)");
  t.add(&P::final_state, "final", "",
        "store realization 0's bodies at t_end (/particles/final/x, v, m): always, never, or auto (at most " +
            to_text(kStoredStateBodies) + " bodies)");
  t.add(&P::animation, "animation", "",
        "record frames (particles and every solver's fields at each frame time) and make animation.mp4 and "
        ".gif");
  t.add(&P::animation_frames, "animation_frames", "1", "frames of the animation, the first at t = 0",
        allowed(at_least(2)));
  t.add(&P::animation_spacing, "animation_spacing", "",
        "frame times equally spaced in [0, t_end], or t = 0 then log-spaced in [animation_t_min, t_end]");
  t.add(&P::animation_t_min, "animation_t_min", "time",
        "first frame after t = 0 when log-spaced; 0 = t_end / 1000", allowed(at_least(0)));
  t.add(
      &P::checkpoint_minutes, "checkpoint_minutes", "min",
      "save the finished realizations to checkpoint.bin, and the running ones' states beside it, this often "
      "(and on SIGTERM, SIGINT) for "
      "`shockgas run --resume`; 0 = only on those signals",
      allowed(at_least(0)));
  return t;
}

// The keys of `table` acting on the part of a Scene that `part` selects.
template <class P>
TableSpec bind(const ParameterTable<P>& table, std::string doc, P& (*part)(Scene&)) {
  TableSpec spec{table.name(), std::move(doc), {}};
  for (const auto& e : table.entries()) {
    KeySpec key{e.info, {}, {}};
    key.set = [&e, part](Scene& s, const ParameterValue& v) { e.set(part(s), v); };
    key.get = [&e, part](const Scene& s) { return e.get(part(const_cast<Scene&>(s))); };
    spec.keys.push_back(std::move(key));
  }
  return spec;
}

std::vector<TableSpec> build_schema() {
  static const ParameterTable<Scene> scene = scene_table();
  static const ParameterTable<SweepParams> sweep = sweep_table();
  static const ParameterTable<OutputParams> output = output_table();
  return {
      bind(
          scene, "what the scene is", +[](Scene& s) -> Scene& { return s; }),
      bind(
          initial_parameters(), "the one initial condition that feeds every model",
          +[](Scene& s) -> InitialParams& { return s.initial; }),
      bind(
          particles::parameters(), "the event-driven gas (present = run it)",
          +[](Scene& s) -> particles::ParticleParams& { return s.particles; }),
      bind(
          continuum::parameters(), "Burgers + continuity solvers (present = run them)",
          +[](Scene& s) -> continuum::ContinuumParams& { return s.continuum; }),
      bind(
          compare::parameters(),
          "the particle analysis, and particles against continuum (present with [continuum] = compare)",
          +[](Scene& s) -> compare::CompareParams& { return s.compare; }),
      TableSpec{
          "statistics",
          "the shock statistics of every realization's clusters at t_end, as `shockgas stats` computes "
          "them, written into the run directory as statistics.h5, .csv, .md and .png (present = compute "
          "them; needs [particles] and its final clusters, particles.final_clusters); no keys",
          {}},
      bind(
          sweep, "variants of the scene run side by side (present = sweep)",
          +[](Scene& s) -> SweepParams& { return s.sweep; }),
      bind(
          output, "what is written besides result.h5 and summary.json",
          +[](Scene& s) -> OutputParams& { return s.output; }),
  };
}

std::string quote(const std::string& s) {
  std::ostringstream out;
  out << toml::value<std::string>(s);
  return out.str();
}

}  // namespace

const KeySpec* TableSpec::find(const std::string& key) const {
  for (const auto& k : keys)
    if (k.info.key == key) return &k;
  return nullptr;
}

std::string TableSpec::keys_text() const {
  std::string list;
  for (const auto& k : keys) list += (list.empty() ? "" : ", ") + k.info.key;
  return list;
}

const std::vector<TableSpec>& scene_schema() {
  static const std::vector<TableSpec> schema = build_schema();
  return schema;
}

const TableSpec* find_table(const std::string& name) {
  for (const auto& t : scene_schema())
    if (t.name == name) return &t;
  return nullptr;
}

ParameterValue from_toml(const toml::node& node) {
  ParameterValue v;
  if (auto b = node.value_exact<bool>()) {
    v = ParameterValue::of(*b);
  } else if (auto i = node.value_exact<std::int64_t>()) {
    v = ParameterValue::of(*i);
  } else if (auto x = node.value_exact<double>()) {
    v = ParameterValue::of(*x);
  } else if (auto s = node.value_exact<std::string>()) {
    v = ParameterValue::of(*s);
  } else if (const auto* arr = node.as_array()) {
    std::vector<ParameterValue> items;
    for (const auto& item : *arr) items.push_back(from_toml(item));
    v = ParameterValue::list(std::move(items));
  }
  v.written = node_text(node);
  return v;
}

std::string toml_text(const ParameterValue& v) {
  using Type = ParameterValue::Type;
  switch (v.type) {
    case Type::boolean:
      return v.boolean ? "true" : "false";
    case Type::integer:
      return std::to_string(v.integer);
    case Type::number:
      return std::isfinite(v.number) ? to_text(v.number) : "nan";
    case Type::text:
      return quote(v.text);
    case Type::list: {
      std::string s = "[";
      for (std::size_t i = 0; i < v.items.size(); ++i) s += (i ? ", " : "") + toml_text(v.items[i]);
      return s + "]";
    }
    case Type::other:
      break;
  }
  return v.written;
}

std::string node_text(const toml::node& node) {
  constexpr std::size_t kLongest = 100;  // a message names a value, it does not reprint a file
  std::ostringstream out;
  if (auto x = node.value_exact<double>())
    out << to_text(*x);
  else
    node.visit([&](const auto& n) { out << n; });
  std::string text = out.str();
  if (text.size() > kLongest)
    text = text.substr(0, kLongest) + "... (" + std::to_string(text.size()) + " characters)";
  return text;
}

}  // namespace shockgas::app
