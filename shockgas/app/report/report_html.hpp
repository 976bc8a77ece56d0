#pragma once
// report.html: a self-contained page of a run's results, beside report.md, for
// a lecture room or a laptop: the animation, the figures of merit with their
// meaning, unit and theory (from the declared output layout, output_layout.hpp),
// the plots, the scene and the provenance. Written by the run from what it
// holds (its summary, the contents of the result.h5 it wrote) and the
// pictures, and by `shockgas animate` again from the directory's files
// (summary.json, result.h5's provenance); everything is embedded and the
// page loads nothing else.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "shockgas/app/output/result_reader.hpp"

namespace shockgas::app {

// Writes dir/report.html (through a temporary name) from its summary.json and
// result.h5. RunError if dir holds no summary.json or result.h5.
void write_report_html(const std::filesystem::path& dir);
// The same from what the run that writes dir holds: its summary and the
// contents of the result.h5 it wrote (written_contents), never read back.
void write_report_html(const std::filesystem::path& dir, const nlohmann::ordered_json& summary,
                       const ResultContents& h5);

}  // namespace shockgas::app
