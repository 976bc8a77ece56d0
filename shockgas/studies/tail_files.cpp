#include "shockgas/studies/tail_files.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/compare/white_noise_references.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_condition.hpp"

namespace shockgas::studies {

namespace {

// Windows [z_lo, z_hi]: from each start, one unit wide and up to the reach.
std::vector<std::pair<double, double>> windows(double reach) {
  std::vector<std::pair<double, double>> w;
  for (const double lo : {1.0, 1.5, 2.0, 2.5, 3.0}) {
    if (lo + 0.2 < reach) w.emplace_back(lo, reach);
    if (lo + 1.0 < reach) w.emplace_back(lo, lo + 1.0);
  }
  return w;
}

}  // namespace

TailEnsemble::TailEnsemble(std::size_t realizations, std::size_t groups)
    : groups_(std::min(realizations, groups)), T_(realizations) {}

void TailEnsemble::add(std::size_t k, TailRealization run) {
  std::vector<compare::TailHistogram>& group = groups_[k % groups_.size()];
  if (group.empty())
    group = std::move(run.histograms);
  else
    for (std::size_t j = 0; j < group.size(); ++j) group[j] += run.histograms[j];
  T_[k] = std::move(run.T);
  collisions_ += static_cast<double>(run.collisions), cpu_seconds_ += run.cpu_seconds;
}

TailFiles::TailFiles(const TailStudyOptions& o) : options_(o) {
  // Realizations are make_initial_bodies({N, seed}, k): the default lattice start,
  // white noise whose intensity D and sticky-gas T t^(2/3) do not depend on N.
  InitialParams ip;
  ip.N = o.sizes.front();
  ip.seed = o.seed;
  const auto exact = compare::white_noise_references(ip);
  if (!exact) throw RunError("tail: the default initial condition is not white noise on a lattice");
  params_.D = exact->D;
  params_.min_clusters = o.min_clusters;
  exact_T_ = exact->temperature_amplitude;
  const std::string dir = o.out_dir + "/";
  phi_ = std::make_unique<CsvWriter>(
      dir + kTailFiles[0],
      std::vector<std::string>{"N", "t", "r", "z", "clusters", "phi", "phi_error", "exact_phi",
                               "local_exponent", "local_exponent_error", "exact_local_bins", "exact_local"});
  windows_ = std::make_unique<CsvWriter>(
      dir + kTailFiles[1], std::vector<std::string>{"N", "t", "r", "z_lo", "z_hi", "bins", "a", "a_error",
                                                    "exact_a", "slope", "slope_error", "exact_slope"});
  runs_ = std::make_unique<CsvWriter>(
      dir + kTailFiles[2],
      std::vector<std::string>{"N", "t", "r", "realizations", "particles", "clusters", "z_reach",
                               "chi_square", "dof", "p_value", "T_t23", "T_t23_error", "exact_T_t23",
                               "collisions", "cpu_seconds"});
}

void TailFiles::add(std::size_t N, const TailEnsemble& runs) {
  for (std::size_t j = 0; j < options_.times.size(); ++j) add_time(N, j, runs);
}

void TailFiles::add_time(std::size_t N, std::size_t j, const TailEnsemble& runs) {
  const double t = options_.times[j], n = static_cast<double>(N), r = options_.r;
  std::vector<compare::TailHistogram> h;
  double clusters = 0;
  for (const auto& group : runs.groups()) h.push_back(group[j]), clusters += group[j].total_clusters();
  std::vector<double> T;
  for (const auto& row : runs.T()) T.push_back(row[j] * std::cbrt(t * t));
  const compare::TailAnalysis a = compare::analyse_tail(h, params_);
  for (const compare::TailPoint& q : a.points) {
    *phi_ << n << t << r << q.z << q.clusters << q.phi.value << q.phi.error << q.exact_phi
          << q.local_exponent.value << q.local_exponent.error << q.exact_local_bins << q.exact_local;
    phi_->end_row();
  }
  for (const auto& [lo, hi] : windows(a.z_reach)) {
    try {
      const compare::TailWindowFit f = compare::fit_tail_window(h, lo, hi, params_);
      *windows_ << n << t << r << lo << hi << double(f.bins) << f.exponent.value << f.exponent.error
                << f.exact_exponent << f.slope.value << f.slope.error << f.exact_slope;
      windows_->end_row();
    } catch (const InputError&) {
      // fewer than 4 tail bins in this window: no row
    }
  }
  const compare::JackknifeEstimate T_mean = compare::jackknife(T.size(), [&](std::size_t leave_out) {
    double s = 0, c = 0;
    for (std::size_t i = 0; i < T.size(); ++i)
      if (i != leave_out) s += T[i], c += 1;
    return s / c;
  });
  const auto R = static_cast<double>(runs.realizations());
  *runs_ << n << t << r << R << n * R << clusters << a.z_reach << a.chi_square << double(a.dof) << a.p_value
         << T_mean.value << T_mean.error << exact_T_ << runs.collisions() << runs.cpu_seconds();
  runs_->end_row();
}

}  // namespace shockgas::studies
