#pragma once
// report.md: the figures of merit of a run with what they mean and the theory
// beside them, written from the run's results.
#include <string>

#include "run_results.hpp"

namespace shockgas::app {

// The whole report of a single run (not a sweep).
std::string report_text(const RunResults& r);

// A number for report.md: 4 significant digits ("nan" stays "nan").
std::string brief(double value);

}  // namespace shockgas::app
