#include "shockgas/app/output/statistics_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/output/layout_version.hpp"
#include "shockgas/compare/white_noise_references.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app {

namespace {

using compare::BinnedStatistic;
using compare::JackknifeEstimate;
using compare::ShockStatistics;

// A number as text with `digits` significant digits (the files: 10); "" for
// NaN (CSV: an empty field).
std::string number(double x, int digits = 10) {
  if (std::isnan(x)) return "";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

// value ± error, the error to two significant digits and the value to the same place.
std::string plus_minus(const JackknifeEstimate& e) {
  if (std::isnan(e.value)) return "not defined (fewer than two clusters)";
  if (!(std::isfinite(e.error) && e.error > 0)) return number(e.value, 4);
  const int decimals = std::max(0, 1 - static_cast<int>(std::floor(std::log10(e.error))));
  char buf[80];
  std::snprintf(buf, sizeof buf, "%.*f ± %.*f", decimals, e.value, decimals, e.error);
  return buf;
}

struct Distribution {
  const char* name;  // in the files
  const BinnedStatistic ShockStatistics::*field;
  const char* unit;  // of the value
  const char* bin_unit;
  const char* meaning;
};

const Distribution kDistributions[] = {
    {"mass", &ShockStatistics::mass, "1", "particles",
     "clusters per realization in each mass bin (bins 1.5, 2.5, 4.5, ... particles)"},
    {"velocity", &ShockStatistics::velocity, "time^(2/3)/length", "length/time^(2/3)",
     "mass fraction per unit z of the clusters, z = (v - U) t^(1/3), U the realization's mean velocity"},
    {"spacing", &ShockStatistics::spacing, "1", "mean spacings",
     "fraction of the gaps between neighbouring clusters per unit gap, gaps in units of the realization's "
     "mean gap"},
};

void write_vector(Hdf5File& f, const std::string& path, const std::vector<double>& v, const std::string& unit,
                  const std::string& description) {
  if (v.empty()) return;
  f.write(path, v.data(), {v.size()}, Storage::float64, unit, description);
}

std::string test_words(const BinnedStatistic& b) {
  if (b.exact.empty()) return "no exact law for this start (white noise on a lattice only)";
  if (!b.chi2) return "too few realizations or clusters for a chi-square";
  // A p that underflows is no p of 0: the chi-square's tail is below what a double holds.
  const std::string p = *b.p_value == 0 ? "p < 1e-300" : "p = " + number(*b.p_value, 2);
  return "chi2 = " + number(*b.chi2, 3) + " on " + std::to_string(b.dof) + " degrees of freedom, " + p +
         (*b.p_value < 0.01 ? " (the law is rejected at the 1 % level)" : "");
}

}  // namespace

compare::StatisticsShape statistics_shape(const Scene& scene) {
  compare::StatisticsShape shape;
  const InitialParams& p = scene.initial;
  shape.N = static_cast<double>(p.N);
  shape.L = domain_length(p);
  shape.t = scene.particles.t_end;
  shape.ring = scene.particles.geometry == particles::Geometry::ring;
  // Lattice and random starts hold particles of mass 1; expressions and files
  // their own masses (the same in every realization).
  const bool own_masses = p.velocities == Velocities::expression || p.velocities == Velocities::file;
  shape.mass = own_masses ? total_mass(make_initial_bodies(p, 0)) : shape.N;
  if (const auto exact = compare::white_noise_references(p)) shape.white_noise_D = exact->D;
  return shape;
}

void write_statistics_h5(const std::filesystem::path& file, const ShockStatistics& s,
                         const StatisticsAbout& about) {
  Hdf5File f = Hdf5File::create(file.string());
  f.set_attribute("/", "layout_version", layout_version_text());
  f.set_attribute("/", "shockgas_version", kVersion);
  f.set_attribute("/", "resolved_parameters", about.resolved);
  std::string sources;
  for (const auto& d : about.sources) sources += (sources.empty() ? "" : "\n") + d;
  f.set_attribute("/", "sources", sources);
  const std::string g = "/statistics";
  auto scalar = [&](const std::string& name, double value, const std::string& unit, const std::string& what) {
    write_vector(f, g + "/" + name, {value}, unit, what);
  };
  scalar("realizations", static_cast<double>(s.realizations), "1", "realizations that reached t_end");
  scalar("left_out", static_cast<double>(about.left_out), "1", "realizations that stopped before t_end");
  scalar("t", s.shape.t, "time", "the time of the clusters");
  scalar("count", s.count.value, "1", "clusters of at least two particles per realization (mean)");
  scalar("count_error", s.count.error, "1", "its jackknife error (NaN from one realization)");
  if (s.count_exact)
    scalar("count_exact", *s.count_exact, "1", "the exact expected number of shocks above 1.5 particles");
  scalar("mass_speed_correlation", s.mass_speed_correlation.value, "1",
         "Pearson correlation of cluster mass and |v - U| over all clusters");
  scalar("mass_speed_correlation_error", s.mass_speed_correlation.error, "1", "its jackknife error");
  for (const Distribution& d : kDistributions) {
    const BinnedStatistic& b = s.*d.field;
    const std::string p = g + "/" + d.name;
    write_vector(f, p + "/edges", b.edges, d.bin_unit, "bin edges");
    write_vector(f, p + "/value", b.value, d.unit, d.meaning);
    write_vector(f, p + "/error", b.error, d.unit, "jackknife error of value (NaN from one realization)");
    write_vector(f, p + "/exact", b.exact, d.unit, "the exact law on the same bins");
    if (b.chi2) {
      f.set_attribute(p + "/value", "chi2", *b.chi2);
      f.set_attribute(p + "/value", "dof", static_cast<double>(b.dof));
      f.set_attribute(p + "/value", "p_value", *b.p_value);
    }
  }
  f.close();
}

// One row per number or bin, each with the unit of its value and of its bins.
void write_statistics_csv(const std::filesystem::path& file, const ShockStatistics& s) {
  std::ostringstream out;
  out << "quantity,bin_low,bin_high,value,error,exact,unit,bin_unit\n";
  out << "realizations,,," << s.realizations << ",,,1,\n";
  out << "count,,," << number(s.count.value) << "," << number(s.count.error) << ","
      << (s.count_exact ? number(*s.count_exact) : "") << ",1,\n";
  out << "mass_speed_correlation,,," << number(s.mass_speed_correlation.value) << ","
      << number(s.mass_speed_correlation.error) << ",,1,\n";
  for (const Distribution& d : kDistributions) {
    const BinnedStatistic& b = s.*d.field;
    if (b.chi2)
      out << d.name << "_chi2,,," << number(*b.chi2) << ",,,1,\n"
          << d.name << "_dof,,," << b.dof << ",,,1,\n"
          << d.name << "_p_value,,," << number(*b.p_value) << ",,,1,\n";
    for (std::size_t j = 0; j < b.value.size(); ++j)
      out << d.name << "," << number(b.edges[j]) << "," << number(b.edges[j + 1]) << "," << number(b.value[j])
          << "," << number(b.error[j]) << "," << (b.exact.empty() ? "" : number(b.exact[j])) << "," << d.unit
          << "," << d.bin_unit << "\n";
  }
  write_file(file, out.str());
}

std::string statistics_markdown(const ShockStatistics& s, const StatisticsAbout& about) {
  std::ostringstream out;
  out << "# Shock statistics: " << about.scene << "\n\n";
  out << s.realizations << " realizations at t = " << number(s.shape.t, 6) << " (N = " << number(s.shape.N, 6)
      << ", L = " << number(s.shape.L, 6) << ", r = " << number(about.r, 6) << ")";
  if (about.left_out > 0) out << "; " << about.left_out << " that stopped before t_end left out";
  out << "; " << s.clusters << " clusters of at least two particles. Errors: jackknife over realizations"
      << (s.realizations < 2 ? " (none: no error estimate from one realization)" : "") << ".\n\n";
  out << "| quantity | measured | exact |\n|---|---|---|\n";
  out << "| clusters per realization | " << plus_minus(s.count) << " | "
      << (s.count_exact ? number(*s.count_exact, 4) : "no exact law") << " |\n";
  out << "| mass distribution | " << s.mass.value.size() << " bins | " << test_words(s.mass) << " |\n";
  out << "| velocity distribution (mass weighted) | " << s.velocity.value.size() << " bins | "
      << test_words(s.velocity) << " |\n";
  out << "| spacing distribution | " << s.spacing.value.size() << " bins | no exact law in shockgas |\n";
  out << "| correlation of mass and speed | " << plus_minus(s.mass_speed_correlation)
      << " | no exact law in shockgas |\n\n";
  if (s.shape.white_noise_D) {
    out << "The exact laws are those of Burgers turbulence from white noise of intensity D = "
        << number(*s.shape.white_noise_D, 4)
        << " (the shock-mass law, shockgas/compare/shock_mass_law.hpp; the mass-weighted cluster velocity "
           "law, shockgas/compare/cluster_velocity_law.hpp): the sticky gas (r = 0) follows them once the "
           "Lagrangian scale a = (4 D t^2)^(1/3) spans many particles and is short against the ring.";
    if (about.r > 0)
      out << " This gas has r = " << number(about.r, 6)
          << " > 0: it approaches them only in its sticky regime, so a departure measures its distance "
             "from the sticky limit as much as the statistics.";
    out << "\n";
  } else {
    out << "This start is not white noise on a lattice: shockgas has no exact law of its shocks, and the "
           "numbers are measured only.\n";
  }
  return out.str();
}

std::string write_statistics(const std::filesystem::path& dir, const StatisticsResult& r) {
  write_statistics_h5(dir / "statistics.h5", r.stats, r.about);
  write_statistics_csv(dir / "statistics.csv", r.stats);
  std::string text = statistics_markdown(r.stats, r.about);
  write_file(dir / "statistics.md", text);
  return text;
}

}  // namespace shockgas::app
