#pragma once
// report.html: a self-contained page of a run's results, beside report.md, for
// a lecture room or a laptop: the animation, the figures of merit with their
// meaning, unit and theory (from the declared output layout, output_layout.hpp),
// the plots, the scene and the provenance. Written from the output directory's
// files alone (summary.json, result.h5's provenance, the PNGs and the movie),
// so `shockgas animate` can write it again; everything is embedded and the
// page loads nothing else.
#include <filesystem>

namespace shockgas::app {

// Writes dir/report.html (through a temporary name). RunError if dir holds no
// summary.json or result.h5.
void write_report_html(const std::filesystem::path& dir);

}  // namespace shockgas::app
