// The studies in order (sections.hpp), then the table of the failures they found.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "shockgas/core/error.hpp"
#include "shockgas/studies/sections.hpp"
#include "shockgas/studies/studies.hpp"

namespace shockgas::studies {

namespace {

constexpr const char* kSectionsVariable = "SHOCKGAS_BENCH_SECTIONS";
// The sections, in the order they run: each a name and its study (sections.hpp).
struct Section {
  const char* name;
  void (*run)(const Context&, FailureLog&);
};
const std::vector<Section> kSections = {{"continuum_wp", continuum_work_precision},
                                        {"continuum_stability", continuum_stability},
                                        {"particles_wp", particle_work_precision},
                                        {"particles_stability", particle_stability}};

bool is_section(const std::string& name) {
  return std::any_of(kSections.begin(), kSections.end(), [&](const Section& s) { return name == s.name; });
}

// SHOCKGAS_BENCH_SECTIONS, comma-separated section names (spaces around them
// ignored), runs only those sections, for re-measuring one chart; unset or
// empty runs them all. InputError for a name that is not a section.
std::vector<std::string> chosen_sections() {
  std::vector<std::string> chosen;
  const char* env = std::getenv(kSectionsVariable);
  if (!env || !*env) {
    for (const Section& s : kSections) chosen.push_back(s.name);
    return chosen;
  }
  std::string list = env;
  for (std::size_t from = 0; from <= list.size();) {
    const std::size_t to = std::min(list.find(',', from), list.size());
    std::string name = list.substr(from, to - from);
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    if (!is_section(name)) {
      std::string names;
      for (const Section& s : kSections) names += (names.empty() ? "" : ", ") + std::string(s.name);
      throw InputError(kSectionsVariable, to_text(list),
                       "comma-separated names among " + names + " (\"" + name + "\" is none of them)");
    }
    chosen.push_back(name);
    from = to + 1;
  }
  return chosen;
}

}  // namespace

bool runs_every_section() {
  const std::vector<std::string> chosen = chosen_sections();
  return std::all_of(kSections.begin(), kSections.end(), [&](const Section& s) {
    return std::find(chosen.begin(), chosen.end(), s.name) != chosen.end();
  });
}

std::string run_studies(const StudyOptions& options) {
  if (options.out_dir.empty()) throw InputError("bench.out", "\"\"", "a directory name");
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec || !std::filesystem::is_directory(options.out_dir))
    throw InputError("bench.out", to_text(options.out_dir), "a directory that can be created");
  Context ctx{options.out_dir, options.full, options.progress};
  FailureLog failures;
  const std::vector<std::string> chosen = chosen_sections();
  // The other sections' failures, as an earlier bench in this directory found them.
  if (!runs_every_section()) failures.keep_earlier(ctx.path("failures.csv"), chosen);
  const auto start = std::chrono::steady_clock::now();
  for (const Section& section : kSections)
    if (std::find(chosen.begin(), chosen.end(), section.name) != chosen.end())
      failures.begin_section(section.name), section.run(ctx, failures);
  failures.write(ctx);
  ctx.log("done", std::to_string(failures.size()) + " failures detected (failures.md), " +
                      fmt(seconds_since(start)) + " s");
  return options.out_dir;
}

}  // namespace shockgas::studies
