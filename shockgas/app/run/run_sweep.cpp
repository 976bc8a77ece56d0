// A [sweep] scene: the same scene once per variant, each in a directory of its
// own, then the variants side by side: a table of one summary key against the
// literature's values (report.md), the T(t) curves and scaled velocity
// distributions of every variant in one result file and in one plot. The
// variants' results are collected in memory as they finish.
#include <optional>
#include <sstream>

#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/output/output_layout.hpp"
#include "shockgas/app/report/plots.hpp"
#include "shockgas/app/report/report.hpp"
#include "shockgas/app/report/report_html.hpp"
#include "shockgas/app/run/run_internal.hpp"
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

std::string table_row(const VariantResult& v, const SweepParams& sweep, std::size_t k) {
  const ordered_json* ours = lookup(v.summary, sweep.reference_key);
  const std::string value = !ours               ? "—"
                            : ours->is_number() ? brief(ours->get<double>())
                            : ours->is_string() ? ours->get<std::string>()
                                                : ours->dump();
  std::string row = "| " + v.label + " | " + value;
  if (!sweep.reference_values.empty())
    row += " | " + (sweep.reference_values[k].empty() ? std::string("—") : sweep.reference_values[k]);
  return row + " |";
}

std::string report(const Scene& scene, const std::vector<VariantResult>& variants) {
  const auto& sweep = scene.sweep;
  std::ostringstream out;
  out << report_header(scene);
  if (!sweep.reference_key.empty()) {
    out << "| variant | " << sweep.reference_key << " (shockgas)"
        << (sweep.reference_values.empty() ? "" : " | reference") << " |\n|---|---|"
        << (sweep.reference_values.empty() ? "" : "---|") << "\n";
    for (std::size_t k = 0; k < variants.size(); ++k) out << table_row(variants[k], sweep, k) << "\n";
    if (!sweep.reference_source.empty()) out << "\nReference: " << sweep.reference_source << "\n";
  }
  out << "\nEach variant's own report, result file and plots are in its directory:\n\n";
  for (const auto& v : variants) out << "- `" << v.directory << "/`: " << v.label << "\n";
  return out.str();
}

}  // namespace

SweepPlan plan_sweep(const Scene& scene) {
  SweepPlan plan;
  plan.variants = expand_sweep(scene);
  for (const auto& v : plan.variants) {
    plan.initial.emplace_back(build_initial(v));
    preflight(v, *plan.initial.back());
  }
  return plan;
}

void run_sweep(const Scene& scene, SweepPlan& plan, const fs::path& dir, const RunOptions& options,
               const EnsembleSource& source) {
  const auto& variants = plan.variants;
  RunResults r;
  r.scene = &scene;
  for (std::size_t k = 0; k < variants.size(); ++k) {
    const std::string label = variants[k].name.substr(scene.name.size() + 1);
    const std::string sub = std::to_string(k) + "-" + slug(label);
    fs::create_directory(dir / sub);
    VariantResult v = run_single(variants[k], *plan.initial[k], dir / sub, options, {}, source);
    plan.initial[k].reset();  // its run is done
    v.label = label;
    v.set = scene.sweep.variants[k];
    v.directory = sub;
    r.variants.push_back(std::move(v));
  }
  ordered_json summary;
  ProgressBar progress(options.progress);
  progress.name_phases("sweep");
  progress.phase("writing result.h5, summary.json, report.md");
  Hdf5File h5 = Hdf5File::create((dir / "result.h5").string());
  for (Part part : {Part::provenance, Part::sweep}) {
    write_part(h5, r, part);
    summarize_part(summary, r, part);
  }
  const ResultContents written = written_contents(h5);  // for report.html: not read back
  h5.close();
  write_file(dir / "summary.json", summary.dump(2) + "\n");
  write_file(dir / "report.md", report(scene, r.variants));
  if (options.plots && scene.output.plots) draw_plots(dir, false, progress);
  progress.phase("writing report.html, manifest.json");
  write_report_html(dir, summary, written);
  write_manifest(dir, scene.name);
}

}  // namespace shockgas::app
