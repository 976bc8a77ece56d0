#pragma once
// report.md: the figures of merit of a run with what they mean and the theory
// beside them, written from the run's results.
#include <string>
#include <utility>
#include <vector>

#include "shockgas/app/output/run_results.hpp"

namespace shockgas::app {

// The whole report of a single run (not a sweep).
std::string report_text(const RunResults& r);

// The section of report.md that gives each phase of the run (the progress
// lines' names; the particles' simulation as "particles: simulation") with its
// wall time in seconds.
std::string phase_times_text(const std::vector<std::pair<std::string, double>>& phases);

// The head of report.md (report_header.cpp): title, the scene's description as
// written, then the run as made: the scene file, the overrides and every key
// the scene or an override set, with the value used.
std::string report_header(const Scene& scene);

// "12.3 %" of a fraction ("nan" stays "nan").
std::string percent(double fraction);

// A number for report.md: 4 significant digits ("nan" stays "nan").
std::string brief(double value);

}  // namespace shockgas::app
