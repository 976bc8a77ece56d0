#pragma once
// The files of `shockgas tail` (tail_study.hpp): each size's realizations
// analysed at each time and written as rows of tail_phi.csv, tail_windows.csv
// and tail_runs.csv.
#include <cstdint>
#include <memory>
#include <vector>

#include "shockgas/compare/velocity_tail.hpp"
#include "shockgas/studies/common.hpp"
#include "shockgas/studies/tail_study.hpp"

namespace shockgas::studies {

// What one realization leaves behind: its folded histograms and temperature at
// each time, its cost.
struct TailRealization {
  std::vector<compare::TailHistogram> histograms;  // one per time
  std::vector<double> T;                           // mass-weighted <(v - <v>)^2> at each time
  std::uint64_t collisions = 0;                    // engine collisions, or the hull's merges
  double cpu_seconds = 0;                          // of its thread
};

// The realizations of one size, their histograms summed into G groups
// (realization k into group k mod G) as they finish: memory does not grow with
// the number of realizations, and the jackknife leaves out groups. Masses are
// whole numbers (unit particle masses), so the sums are exact and do not depend
// on the order in which realizations finish.
class TailEnsemble {
 public:
  TailEnsemble(std::size_t realizations, std::size_t groups);
  void add(std::size_t k, TailRealization run);  // not thread-safe: the caller locks
  std::size_t realizations() const { return T_.size(); }
  const std::vector<std::vector<compare::TailHistogram>>& groups() const { return groups_; }  // [group][time]
  const std::vector<std::vector<double>>& T() const { return T_; }  // [realization][time]
  double collisions() const { return collisions_; }
  double cpu_seconds() const { return cpu_seconds_; }

 private:
  std::vector<std::vector<compare::TailHistogram>> groups_;
  std::vector<std::vector<double>> T_;
  double collisions_ = 0, cpu_seconds_ = 0;
};

class TailFiles {
 public:
  explicit TailFiles(const TailStudyOptions& options);  // writes the headers
  // The realizations of size N, analysed at each time.
  void add(std::size_t N, const TailEnsemble& runs);

 private:
  void add_time(std::size_t N, std::size_t j, const TailEnsemble& runs);
  TailStudyOptions options_;
  compare::TailParams params_;
  double exact_T_ = 0;  // T t^(2/3) of the exact mass-weighted law
  std::unique_ptr<CsvWriter> phi_, windows_, runs_;
};

}  // namespace shockgas::studies
