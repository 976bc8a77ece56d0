#pragma once
// The files of `shockgas stats` (statistics_run.hpp), from one
// compare::ShockStatistics: statistics.h5 (group /statistics, every dataset
// with its unit and meaning), statistics.csv (one row per bin or number) and
// statistics.md (the numbers in words, each law with where it holds).
#include <filesystem>
#include <string>
#include <vector>

#include "shockgas/compare/shock_statistics.hpp"

namespace shockgas::app {

// Where the statistics come from, for the files' provenance.
struct StatisticsAbout {
  std::string scene;                 // the scene's name
  std::string resolved;              // its resolved parameters (one source's: they agree but for the seed)
  std::vector<std::string> sources;  // the directories, as given
  std::size_t left_out = 0;          // realizations that stopped before t_end
  double r = 0;                      // particles.r of the gas
};

void write_statistics_h5(const std::filesystem::path& file, const compare::ShockStatistics& s,
                         const StatisticsAbout& about);
void write_statistics_csv(const std::filesystem::path& file, const compare::ShockStatistics& s);
// statistics.md's text, also what the command prints.
std::string statistics_markdown(const compare::ShockStatistics& s, const StatisticsAbout& about);

}  // namespace shockgas::app
