#include "shockgas/core/initial_condition.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "shockgas/core/error.hpp"
#include "shockgas/core/expression.hpp"
#include "shockgas/core/initial_stream.hpp"

namespace shockgas {

namespace {

bool is_one_of(const std::string& s, std::initializer_list<const char*> options) {
  return std::any_of(options.begin(), options.end(), [&](const char* o) { return s == o; });
}

// Reads `x v [m]` lines; '#' starts a comment.
Bodies read_bodies_file(const std::string& path) {
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
    if (!(row >> x)) continue;  // blank line
    const std::string where = path + ":" + std::to_string(lineno);
    if (!(row >> v)) throw InputError("initial.file", to_text(line), "lines `x v [m]`", where);
    if (!(row >> m)) m = 1.0;
    if (!std::isfinite(x) || !std::isfinite(v) || !std::isfinite(m) || m <= 0)
      throw InputError("initial.file", to_text(line), "finite x, v and mass m > 0", where);
    if (!b.x.empty() && x < b.x.back())
      throw InputError("initial.file", to_text(line), "lines sorted by x", where);
    b.push_back(x, v, m);
  }
  if (b.size() < 2) throw InputError("initial.file", to_text(path), "a file with at least 2 bodies");
  return b;
}

void subtract_mean(Bodies& b) {
  const double mean = total_momentum(b) / total_mass(b);
  for (auto& v : b.v) v -= mean;
}

}  // namespace

double domain_length(const InitialParams& p) {
  if (p.velocities == "expression") return p.domain;
  return p.L > 0 ? p.L : static_cast<double>(p.N);
}

void validate(const InitialParams& p) {
  require(p.N >= 2, "initial.N", p.N, "an integer N >= 2");
  require(is_one_of(p.positions, {"lattice", "random"}), "initial.positions", p.positions,
          "\"lattice\" or \"random\"");
  require(is_one_of(p.velocities, {"uniform", "gaussian", "file", "expression"}), "initial.velocities",
          p.velocities, "\"uniform\", \"gaussian\", \"file\" or \"expression\"");
  require_above("initial.amplitude", p.amplitude, 0.0);
  require(std::isfinite(p.L) && p.L >= 0, "initial.L", p.L, "a finite length >= 0 (0 means L = N)");
  require_above("initial.domain", p.domain, 0.0);
  if (p.velocities == "file") {
    require(!p.file.empty() && std::filesystem::is_regular_file(p.file), "initial.file", p.file,
            "an existing text file with columns x v [m] (velocities = \"file\")");
  }
  if (p.velocities == "expression") {
    Expression(p.v0, "initial.v0").require_finite_on(0.0, p.domain);
    Expression rho(p.rho0, "initial.rho0");
    rho.require_finite_on(0.0, p.domain);
    for (int i = 0; i <= 1000; ++i) {
      const double x = p.domain * i / 1000.0;
      require(rho(x) > 0, "initial.rho0", p.rho0, "a density > 0 on the domain (it is " +
                                                      to_text(rho(x)) + " at x = " + to_text(x) + ")");
    }
  }
}

Bodies make_initial_bodies(const InitialParams& p, std::uint64_t realization) {
  if (p.velocities == "file") return read_bodies_file(p.file);
  Bodies b;
  if (InitialStream::streamable(p)) {
    InitialStream stream(p, realization);
    b.x.resize(p.N), b.v.resize(p.N), b.m.resize(p.N);
    stream.next(p.N, b.x.data(), b.v.data(), b.m.data());
    return b;
  }
  const Expression v0(p.v0, "initial.v0"), rho0(p.rho0, "initial.rho0");
  const double dx = domain_length(p) / p.N;
  for (std::size_t i = 0; i < p.N; ++i) {
    const double x = (i + 0.5) * dx;
    b.push_back(x, v0(x), rho0(x) * dx);
  }
  if (p.remove_mean) subtract_mean(b);
  return b;
}

InitialField make_initial_field(const InitialParams& p, std::uint64_t realization) {
  InitialField f;
  f.length = domain_length(p);
  if (p.velocities == "expression") {
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
