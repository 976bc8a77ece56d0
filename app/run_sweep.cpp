// A [sweep] scene: the same scene once per variant, each in a directory of its
// own, then the variants side by side: a table of one summary key against the
// literature's values (report.md), the T(t) curves and scaled velocity
// distributions of every variant in one result file and in one plot.
#include <fstream>
#include <sstream>

#include "plots.hpp"
#include "run_state.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

std::string slug(const std::string& text) {
  std::string s;
  for (char c : text) s += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ? c : '_';
  return s;
}

const ordered_json* lookup(const ordered_json& j, const std::string& dotted) {
  const ordered_json* node = &j;
  std::stringstream in(dotted);
  std::string part;
  while (std::getline(in, part, '.')) {
    if (!node->is_object() || !node->contains(part)) return nullptr;
    node = &(*node)[part];
  }
  return node;
}

// Copies the datasets a side-by-side plot needs from a variant's result file.
void copy_series(const fs::path& variant_h5, Hdf5File& h5, const std::string& group) {
  const Hdf5File in = Hdf5File::open(variant_h5.string());
  for (const auto& d : in.datasets()) {
    const bool wanted = d.path == "/particles/t" || d.path == "/particles/T" || d.path == "/particles/T_stderr" ||
                        d.path.rfind("/particles/histogram/", 0) == 0;
    if (!wanted) continue;
    const auto data = in.read(d.path);
    if (d.shape.size() == 2)
      h5.write_matrix(group + d.path, data, d.shape[0], d.shape[1], d.unit, d.description);
    else
      h5.write(group + d.path, data, d.unit, d.description);
  }
}

std::string table_row(const std::string& label, const ordered_json* ours, const SweepParams& sweep, std::size_t k) {
  std::string row = "| " + label + " | " + (ours && ours->is_number() ? brief(ours->get<double>()) : "—");
  if (!sweep.reference_values.empty())
    row += " | " + (sweep.reference_values[k].empty() ? std::string("—") : sweep.reference_values[k]);
  return row + " |";
}

void write_report(const fs::path& dir, const Scene& scene, const ordered_json& summary) {
  const auto& sweep = scene.sweep;
  std::ofstream out(dir / "report.md");
  out << "# shockgas report: " << scene.name << "\n\n";
  if (!scene.description.empty()) out << scene.description << "\n\n";
  if (!sweep.reference_key.empty()) {
    out << "| variant | " << sweep.reference_key << " (shockgas)"
        << (sweep.reference_values.empty() ? "" : " | reference") << " |\n|---|---|"
        << (sweep.reference_values.empty() ? "" : "---|") << "\n";
    for (std::size_t k = 0; k < summary["variants"].size(); ++k) {
      const auto& v = summary["variants"][k];
      out << table_row(v["label"].get<std::string>(), lookup(v["summary"], sweep.reference_key), sweep, k) << "\n";
    }
    if (!sweep.reference_source.empty()) out << "\nReference: " << sweep.reference_source << "\n";
  }
  out << "\nEach variant's own report, result file and plots are in its directory:\n\n";
  for (const auto& v : summary["variants"])
    out << "- `" << v["directory"].get<std::string>() << "/`: " << v["label"].get<std::string>() << "\n";
}

}  // namespace

std::string run_sweep(const Scene& scene, const fs::path& dir, const RunOptions& options) {
  const std::vector<Scene> variants = expand_sweep(scene);  // every variant valid before any work
  for (const auto& v : variants) preflight(v);
  PartialOutputs outputs(dir);
  ordered_json summary;
  {
    Hdf5File h5 = Hdf5File::create(outputs.h5_path());
    write_provenance(h5, summary, scene);
    for (std::size_t k = 0; k < variants.size(); ++k) {
      const std::string label = variants[k].name.substr(scene.name.size() + 1);
      const std::string sub = std::to_string(k) + "-" + slug(label);
      run_single(variants[k], dir / sub, options);
      std::ifstream in(dir / sub / "summary.json");
      ordered_json variant_summary = ordered_json::parse(in);
      summary["variants"].push_back({{"label", label},
                                     {"set", scene.sweep.variants[k]},
                                     {"directory", sub},
                                     {"summary", variant_summary}});
      const std::string group = "/sweep/" + std::to_string(k);
      copy_series(dir / sub / "result.h5", h5, group);
      h5.set_attribute(group, "label", label);
      h5.set_attribute(group, "set", scene.sweep.variants[k]);
    }
  }
  outputs.commit(summary);
  write_report(dir, scene, summary);
  if (options.plots && scene.output.plots) make_plots(dir.string());
  return dir.string();
}

}  // namespace shockgas::app
