// shockgas.run, run_toml and load: a scene run as the command runs it, its
// outputs kept in memory under the names of the declared layout (and written
// to the usual directory when asked), or read back from a finished run.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <variant>

#include "arrays.hpp"
#include "bindings.hpp"
#include "interruptible.hpp"
#include "keywords.hpp"
#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/files/file_problem.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/jobs/run_scene.hpp"
#include "shockgas/app/jobs/statistics_run.hpp"
#include "shockgas/app/run/captured_outputs.hpp"
#include "shockgas/app/run/resources.hpp"
#include "shockgas/app/scene/scene_schema.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::python {

namespace {

constexpr const char* kDictOrigin = "<dict>";

// A scene given as a nested dict, {"particles": {"r": 0.5}, ...}, as TOML text.
std::string dict_scene_text(const py::dict& scene) {
  std::string text;
  for (const auto& [table, keys] : scene) {
    const std::string name = py::str(table);
    if (!py::isinstance<py::dict>(keys))
      throw InputError(name, to_parameter(keys).written, "a table: a dict of keys, e.g. {\"r\": 0.5}");
    text += "[" + name + "]\n";
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(keys)) {
      const ParameterValue v = to_parameter(value);
      const std::string dotted = name + "." + std::string(py::str(key));
      if (v.type == ParameterValue::Type::other)
        throw InputError(dotted, v.written, "a number, string, boolean or list of them");
      text +=
          app::toml_text(ParameterValue::of(std::string(py::str(key)))) + " = " + app::toml_text(v) + "\n";
    }
  }
  return text;
}

// {"particles.r": 0.5} (or ["particles.r=0.5"]) as the command's --set assignments.
std::vector<std::string> override_list(const py::handle& overrides) {
  std::vector<std::string> out;
  if (overrides.is_none()) return out;
  if (py::isinstance<py::dict>(overrides)) {
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(overrides))
      out.push_back(std::string(py::str(key)) + "=" + app::toml_text(to_parameter(value)));
    return out;
  }
  for (const py::handle item : py::iter(overrides)) out.push_back(item.cast<std::string>());
  return out;
}

// An error of a dict scene located where the caller wrote it: scene['particles']['r']
// or overrides['particles.r'], instead of a line of the generated text.
InputError located_in_python(const InputError& e) {
  const std::string& where = e.where();
  if (where.rfind("--set ", 0) == 0) {
    const std::string assignment = where.substr(6);
    return e.located("overrides['" + assignment.substr(0, assignment.find('=')) + "']");
  }
  if (where.rfind(kDictOrigin, 0) != 0) return e;
  if (const auto* file = dynamic_cast<const app::FileProblem*>(&e))  // the scene as a whole: "runs nothing"
    return app::FileProblem("scene", "scene", file->problem(), file->detail());
  const auto dot = e.key().find('.');
  if (dot == std::string::npos) return e.located("scene['" + e.key() + "']");
  return e.located("scene['" + e.key().substr(0, dot) + "']['" + e.key().substr(dot + 1) + "']");
}

// The values as the file stores them (storage.hpp): float32 rounded to the
// nearest, integers exact, float64 as they are.
py::array stored_array(std::vector<double>&& values, const std::vector<py::ssize_t>& shape, app::Storage s) {
  if (s == app::Storage::float32) return to_numpy(std::vector<float>(values.begin(), values.end()), shape);
  if (s == app::Storage::integer)
    return to_numpy(std::vector<std::int64_t>(values.begin(), values.end()), shape);
  return to_numpy(std::move(values), shape);
}

py::dict outputs_dict(app::CapturedOutputs&& out, const std::string& directory,
                      const std::vector<std::string>& notes = {}) {
  py::dict datasets, units, descriptions, attributes;
  for (auto& [path, d] : out.datasets) {
    std::vector<py::ssize_t> shape(d.shape.begin(), d.shape.end());
    datasets[py::str(path)] = stored_array(std::move(d.data), shape, d.storage);
    units[py::str(path)] = d.unit;
    descriptions[py::str(path)] = d.description;
  }
  for (const auto& [path, value] : out.attributes)
    attributes[py::str(path)] = std::visit([](const auto& v) { return py::cast(v); }, value);
  py::dict d;
  d["datasets"] = datasets;
  d["units"] = units;
  d["descriptions"] = descriptions;
  d["attributes"] = attributes;
  d["summary"] = py::module_::import("json").attr("loads")(out.summary.dump());
  d["directory"] = directory.empty() ? py::object(py::none()) : py::object(py::str(directory));
  d["notes"] = notes;
  return d;
}

// One scene (no sweep) kept in memory, and written to out_dir if given (its
// directory locked and staged before any work, as the command's).
app::CapturedOutputs capture_single(const app::Scene& scene, const std::string& out_dir, bool plots,
                                    ProgressRelay& relay) {
  std::optional<app::RunDirectory> dir;
  if (!out_dir.empty()) dir.emplace(out_dir, scene.name, false);
  const InitialCondition initial = app::build_initial(scene);
  app::preflight(scene, initial);
  auto listener = [&relay](const std::string& stage, double f, double t) { relay.report(stage, f, t); };
  app::CapturedOutputs captured;
  if (!dir) {
    app::ProgressBar bar(false, listener);
    app::compute_parts(scene, initial, bar, app::capture_into(captured));
  } else {
    app::RunOptions options;
    options.out_dir = out_dir, options.progress = false, options.plots = plots,
    options.on_progress = listener;
    app::into_run_directory(*dir, out_dir, scene, options, [&](const std::filesystem::path& staging) {
      app::run_single(scene, initial, staging, options, app::capture_into(captured));
    });
  }
  return captured;
}

// A [sweep] scene into out_dir, as the command runs it; the result is its sweep file.
app::CapturedOutputs capture_sweep(const app::Scene& scene, const std::string& out_dir, bool plots,
                                   ProgressRelay& relay) {
  require(!out_dir.empty(), "sweep", std::string("(table)"),
          "a [sweep] scene with out=DIR: each variant is written into a directory of its own");
  app::RunDirectory dir(out_dir, scene.name, false);
  app::RunOptions options;
  options.out_dir = out_dir, options.progress = false, options.plots = plots;
  options.on_progress = [&relay](const std::string& stage, double f, double t) { relay.report(stage, f, t); };
  app::SweepPlan plan = app::plan_sweep(scene);
  app::into_run_directory(dir, out_dir, scene, options, [&](const std::filesystem::path& staging) {
    app::run_sweep(scene, plan, staging, options);
  });
  return app::read_outputs(out_dir);
}

py::dict run_scene(const std::function<app::Scene()>& parse, const py::object& out, bool plots,
                   const py::object& progress) {
  const std::string out_dir = out.is_none() ? "" : std::string(py::str(out));
  std::vector<std::string> notes;  // what the command prints as "shockgas: note: ..."
  try {
    app::CapturedOutputs captured = run_interruptible<app::CapturedOutputs>(
        [&](ProgressRelay& relay) {
          const app::Scene scene = parse();
          for (const app::Scene& s :
               scene.has_sweep ? app::expand_sweep(scene) : std::vector<app::Scene>{scene})
            if (!s.solver_note.empty())
              notes.push_back((scene.has_sweep ? s.name + ": " : "") + s.solver_note);
          app::check_memory(scene);  // as `shockgas run` does, before any work
          return scene.has_sweep ? capture_sweep(scene, out_dir, plots, relay)
                                 : capture_single(scene, out_dir, plots, relay);
        },
        progress);
    return outputs_dict(std::move(captured), out_dir, notes);
  } catch (const InputError& e) {
    throw located_in_python(e);
  }
}

py::dict run_path(const std::string& path, const py::handle& overrides, const py::object& out, bool plots,
                  const py::object& progress) {
  const std::vector<std::string> sets = override_list(overrides);
  return run_scene([&] { return app::load_scene(path, sets); }, out, plots, progress);
}

// TOML text; origin names it in messages ("<toml>:3: ..."); a dict scene's text has origin kDictOrigin.
py::dict run_text(const std::string& text, const std::string& origin, const py::handle& overrides,
                  const py::object& out, bool plots, const py::object& progress) {
  const std::vector<std::string> sets = override_list(overrides);
  return run_scene(
      [&] {
        app::Scene scene = app::parse_scene(text, origin, sets);
        if (scene.name == origin) scene.name = "scene";  // no [scene] name and no file to name it
        return scene;
      },
      out, plots, progress);
}

py::dict load(const std::string& path) {
  app::CapturedOutputs out = app::read_outputs(path);
  const std::filesystem::path p(path);
  return outputs_dict(std::move(out), (std::filesystem::is_directory(p) ? p : p.parent_path()).string());
}

// Every scene key: table, key, kind, unit, default, meaning, allowed values.
py::list scene_keys() {
  const app::Scene defaults;
  py::list out;
  for (const app::TableSpec& table : app::scene_schema())
    for (const app::KeySpec& key : table.keys)
      out.append(py::dict(py::arg("table") = table.name, py::arg("key") = key.info.key,
                          py::arg("kind") = key.info.kind, py::arg("unit") = key.info.unit,
                          py::arg("default") = app::toml_text(key.get(defaults)),
                          py::arg("doc") = key.info.doc, py::arg("allowed") = key.info.allowed()));
  return out;
}

// Keywords of the tables `tables` as a dict scene: each keyword goes to the first
// of them that declares it; one that none declares is refused, naming it.
py::dict keywords_scene(const std::vector<std::string>& tables, const std::string& function,
                        const py::kwargs& kwargs) {
  py::dict scene, leftover;
  for (const auto& [key, value] : kwargs) {
    const std::string name = py::str(key);
    const auto declares = [&](const std::string& t) { return app::find_table(t)->find(name) != nullptr; };
    const auto table = std::find_if(tables.begin(), tables.end(), declares);
    if (table == tables.end()) {
      leftover[key] = value;
      continue;
    }
    const py::str t(*table);
    if (!scene.contains(t)) scene[t] = py::dict();
    scene[t][key] = value;
  }
  // Each keyword once: a key declared by two of the tables (solver of [particles]
  // and of [compare]) is the first's.
  std::string accepted;
  std::vector<std::string> listed;
  for (const std::string& t : tables)
    for (const app::KeySpec& key : app::find_table(t)->keys)
      if (std::find(listed.begin(), listed.end(), key.info.key) == listed.end()) {
        accepted += (accepted.empty() ? "" : ", ") + key.info.key;
        listed.push_back(key.info.key);
      }
  refuse_leftover(leftover, function, accepted);
  return scene;
}

}  // namespace

void bind_run(py::module_& m) {
  m.def("_keywords_scene", &keywords_scene, py::arg("tables"), py::arg("function"));
  m.def("_run_path", &run_path, py::arg("path"), py::arg("overrides"), py::arg("out"), py::arg("plots"),
        py::arg("progress"));
  m.def("_run_text", &run_text, py::arg("text"), py::arg("origin"), py::arg("overrides"), py::arg("out"),
        py::arg("plots"), py::arg("progress"));
  m.def("_dict_scene_text", [](const py::dict& scene) {
    try {
      return dict_scene_text(scene);
    } catch (const InputError& e) {
      throw e.located("scene['" + e.key().substr(0, e.key().find('.')) + "']");
    }
  });
  m.attr("_dict_origin") = kDictOrigin;
  m.def("_load", &load, py::arg("path"));
  m.def(
      "_statistics",
      [](const std::vector<std::string>& dirs, const std::string& out, bool plots) {
        const py::gil_scoped_release unlocked;
        return app::run_statistics({dirs, out, false, plots, true});
      },
      py::arg("dirs"), py::arg("out"), py::arg("plots"));
  m.def("_scene_keys", &scene_keys);
  m.def("_layout", [] {
    py::list out;
    for (const app::LayoutEntry& e : app::output_layout())
      out.append(py::dict(py::arg("kind") = e.kind == app::LayoutEntry::Kind::dataset     ? "dataset"
                                            : e.kind == app::LayoutEntry::Kind::attribute ? "attribute"
                                                                                          : "summary",
                          py::arg("path") = e.path, py::arg("unit") = e.unit,
                          py::arg("description") = e.description, py::arg("when") = e.when,
                          py::arg("type") = e.kind == app::LayoutEntry::Kind::dataset
                                                ? app::storage_name(e.storage)
                                                : std::string()));
    return out;
  });
}

}  // namespace shockgas::python
