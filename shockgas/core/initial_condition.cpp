#include "shockgas/core/initial_condition.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>

#include "shockgas/core/error.hpp"
#include "shockgas/core/expression.hpp"
#include "shockgas/core/initial_stream.hpp"

namespace shockgas {

namespace {

// Whether nothing but blanks is left in row.
bool at_end(std::istringstream& row) {
  row >> std::ws;
  return row.eof();
}

// Reads `x v [m]` lines; '#' starts a comment. The file must hold N bodies:
// N is what the summary reports and, at L = 0, sets the ring's length.
Bodies read_bodies_file(const std::string& path, std::size_t N) {
  std::ifstream in(path);
  if (!in) throw InputError("initial.file", to_text(path), "a readable text file with columns x v [m]");
  Bodies b;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream row(line);
    double x, v, m = 1.0;
    if (at_end(row)) continue;  // blank line
    const std::string where = path + ":" + std::to_string(lineno);
    if (!(row >> x))
      throw InputError("initial.file", to_text(line), "lines `x v [m]` ('#' starts a comment)", where);
    if (!(row >> v)) throw InputError("initial.file", to_text(line), "lines `x v [m]`", where);
    if (!at_end(row) && !(row >> m))
      throw InputError("initial.file", to_text(line), "lines `x v [m]`", where);
    if (!at_end(row))
      throw InputError("initial.file", to_text(line), "lines `x v [m]`: two or three numbers", where);
    if (!std::isfinite(x) || !std::isfinite(v) || !std::isfinite(m) || m <= 0)
      throw InputError("initial.file", to_text(line), "finite x, v and mass m > 0", where);
    if (!b.x.empty() && x < b.x.back())
      throw InputError("initial.file", to_text(line), "lines sorted by x", where);
    b.push_back(x, v, m);
  }
  if (b.size() < 2) throw InputError("initial.file", to_text(path), "a file with at least 2 bodies");
  require(b.size() == N, "initial.N", N,
          "the number of bodies in initial.file (" + std::to_string(b.size()) + " in " + path + ")");
  return b;
}

void subtract_mean(Bodies& b) {
  const double mean = total_momentum(b) / total_mass(b);
  for (auto& v : b.v) v -= mean;
}

}  // namespace

const ParameterTable<InitialParams>& initial_parameters() {
  static const ParameterTable<InitialParams> table = [] {
    using P = InitialParams;
    ParameterTable<P> t("initial");
    t.add(&P::N, "N", "1", "number of particles", allowed(at_least(2)));
    t.add(&P::positions, "positions", "", "initial positions: equally spaced, or uniform random (sorted)");
    t.add(&P::velocities, "velocities", "",
          "initial velocities: uniform on [-amplitude, amplitude], Gaussian (sd amplitude), from file, or "
          "v0(x)");
    t.add(&P::amplitude, "amplitude", "length/time", "velocity scale", allowed(above(0)));
    t.add(&P::remove_mean, "remove_mean", "", "subtract the mean velocity");
    t.add(&P::file, "file", "", "bodies `x v [m]` per line, sorted by x; initial.N must count them",
          described("an existing text file (velocities = \"file\")"));
    t.add(&P::seed, "seed", "", "random seed (realization k uses a seed derived from it)",
          allowed(at_least(0)));
    t.add(&P::L, "L", "length", "ring length; 0 means L = N (unit spacing)", allowed(at_least(0)));
    t.add(&P::v0, "v0", "length/time", "v0(x) for velocities = \"expression\"",
          described("an expression in x, finite on the domain"));
    t.add(&P::rho0, "rho0", "mass/length", "rho0(x) for velocities = \"expression\"",
          described("an expression in x, > 0 on the domain"));
    t.add(&P::domain, "domain", "length",
          "period of v0, rho0 (domain [0, domain)) for velocities = \"expression\"", allowed(above(0)));
    return t;
  }();
  return table;
}

double ring_length(double L, std::size_t N) { return L == 0 ? static_cast<double>(N) : L; }

double domain_length(const InitialParams& p) {
  if (p.velocities == Velocities::expression) return p.domain;
  return ring_length(p.L, p.N);
}

void validate(const InitialParams& p) {
  initial_parameters().check(p);
  // Sums over the bodies stay finite (positions i L / N, the momentum, the
  // temperature sum m v^2): bounds far beyond any physics, refused here rather
  // than as an infinity inside the work, under a name the scene never wrote.
  const double n = std::max(static_cast<double>(p.N), 1.0), most = std::numeric_limits<double>::max() / 64;
  require(p.L <= most / n, "initial.L", p.L,
          "at most " + to_text(most / n, 3) + " for initial.N = " + std::to_string(p.N) +
              " (the positions, up to N L, must stay within the range of doubles)");
  require(p.amplitude <= std::sqrt(most / n), "initial.amplitude", p.amplitude,
          "at most " + to_text(std::sqrt(most / n), 3) + " for initial.N = " + std::to_string(p.N) +
              " (the temperature, a sum of N v^2, must stay within the range of doubles)");
  if (p.velocities == Velocities::file) {
    require(!p.file.empty() && std::filesystem::is_regular_file(p.file), "initial.file", p.file,
            "an existing text file with columns x v [m] (velocities = \"file\")");
  }
  if (p.velocities == Velocities::expression) {
    Expression(p.v0, "initial.v0").require_finite_on(0.0, p.domain);
    Expression rho(p.rho0, "initial.rho0");
    rho.require_finite_on(0.0, p.domain);
    for (int i = 0; i <= 1000; ++i) {
      const double x = p.domain * i / 1000.0;
      require(rho(x) > 0, "initial.rho0", p.rho0,
              "a density > 0 on the domain (it is " + to_text(rho(x)) + " at x = " + to_text(x) + ")");
    }
  }
}

Bodies make_initial_bodies(const InitialParams& p, std::uint64_t realization) {
  if (p.velocities == Velocities::file) return read_bodies_file(p.file, p.N);
  Bodies b;
  if (InitialStream::streamable(p)) {
    InitialStream stream(p, realization);
    b.x.resize(p.N), b.v.resize(p.N), b.m.resize(p.N);
    stream.next(p.N, b.x.data(), b.v.data(), b.m.data());
    return b;
  }
  b = lattice_bodies(make_initial_field(p, realization), p.N);
  if (p.remove_mean) subtract_mean(b);
  return b;
}

Bodies lattice_bodies(const InitialField& f, std::size_t N) {
  Bodies b;
  b.reserve(N);
  const double dx = f.length / N;
  for (std::size_t i = 0; i < N; ++i) {
    const double x = (i + 0.5) * dx;
    b.push_back(x, f.v0(x), f.rho0(x) * dx);
  }
  return b;
}

InitialCondition::InitialCondition(const InitialParams& p, Keep keep)
    : params_(p), held_(keep == Keep::bodies || !InitialStream::streamable(p)) {
  validate(p);
  if (!held_) {
    field_.length = domain_length(p);
    return;
  }
  field_ = make_initial_field(p, 0);
  if (!field_.from_bodies()) expression_bodies_ = make_initial_bodies(p, 0);
}

const Bodies& InitialCondition::bodies() const {
  if (!held_)
    throw RunError("the initial condition does not hold realization 0: read it with stream_realization");
  return field_.from_bodies() ? field_.bodies : expression_bodies_;
}

bool InitialCondition::depends_on_realization() const { return InitialStream::streamable(params_); }

Bodies InitialCondition::realization(std::uint64_t k) const {
  return held_ && (k == 0 || !depends_on_realization()) ? bodies() : make_initial_bodies(params_, k);
}

InitialField make_initial_field(const InitialParams& p, std::uint64_t realization) {
  InitialField f;
  f.length = domain_length(p);
  if (p.velocities == Velocities::expression) {
    auto v0 = std::make_shared<Expression>(p.v0, "initial.v0");
    auto rho0 = std::make_shared<Expression>(p.rho0, "initial.rho0");
    f.v0 = [v0](double x) { return (*v0)(x); };
    f.rho0 = [rho0](double x) { return (*rho0)(x); };
  } else {
    f.bodies = make_initial_bodies(p, realization);
  }
  return f;
}

}  // namespace shockgas
