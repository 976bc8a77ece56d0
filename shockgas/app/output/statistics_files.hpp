#pragma once
// The shock statistics' files, from one compare::ShockStatistics, written by
// `shockgas stats` (jobs/statistics_run.hpp) and by a run whose scene has
// [statistics] (run/stage_statistics.cpp): statistics.h5 (group /statistics,
// every dataset with its unit and meaning), statistics.csv (one row per bin or
// number) and statistics.md (the numbers in words, each law with where it
// holds); statistics.png is drawn from statistics.csv.
#include <filesystem>
#include <string>
#include <vector>

#include "shockgas/app/scene/scene.hpp"
#include "shockgas/compare/shock_statistics.hpp"

namespace shockgas::app {

// Where the statistics come from, for the files' provenance.
struct StatisticsAbout {
  std::string scene;                 // the scene's name
  std::string resolved;              // its resolved parameters (one source's: they agree but for the seed)
  std::vector<std::string> sources;  // the directories, as given (a run's own [statistics]: its scene file)
  std::size_t left_out = 0;          // realizations that stopped before t_end
  double r = 0;                      // particles.r of the gas
};

// The statistics with where they come from: what a run with [statistics] holds.
struct StatisticsResult {
  compare::ShockStatistics stats;
  StatisticsAbout about;
};

// The name a statistics run of `scene` gives its directory and manifest:
// "<scene>-stats" (statistics.h5 holds the scene's own parameters).
inline std::string statistics_run_name(const std::string& scene) { return scene + "-stats"; }

// The shape compare::shock_statistics needs (white-noise D where the start is
// white noise on a lattice).
compare::StatisticsShape statistics_shape(const Scene& scene);

void write_statistics_h5(const std::filesystem::path& file, const compare::ShockStatistics& s,
                         const StatisticsAbout& about);
void write_statistics_csv(const std::filesystem::path& file, const compare::ShockStatistics& s);
// statistics.md's text, also what the command prints.
std::string statistics_markdown(const compare::ShockStatistics& s, const StatisticsAbout& about);

// statistics.h5, statistics.csv and statistics.md into dir; returns the markdown.
std::string write_statistics(const std::filesystem::path& dir, const StatisticsResult& r);

}  // namespace shockgas::app
