#pragma once
// report.md: the figures of merit of a run with what they mean and the theory
// beside them, written from the run's results.
#include <string>

#include "shockgas/app/output/run_results.hpp"

namespace shockgas::app {

// The whole report of a single run (not a sweep).
std::string report_text(const RunResults& r);

// The head of report.md (report_header.cpp): title, the scene's description as
// written, then the run as made: the scene file, the overrides and every key
// the scene or an override set, with the value used.
std::string report_header(const Scene& scene);

// "12.3 %" of a fraction ("nan" stays "nan").
std::string percent(double fraction);

// A number for report.md: 4 significant digits ("nan" stays "nan").
std::string brief(double value);

}  // namespace shockgas::app
