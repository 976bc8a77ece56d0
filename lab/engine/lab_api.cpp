#include "lab/engine/lab_api.hpp"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <map>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "lab/engine/lab_session.hpp"

namespace {

using shockgas::lab::LabFrame;
using shockgas::lab::LabSession;

struct State {
  std::unique_ptr<LabSession> session;
  std::map<std::string, std::vector<double>> arrays;
  std::map<std::string, double> values;
  std::string message, digest;
};

State& state() {
  static State s;
  return s;
}

// Runs f; on an exception keeps its text for lab_message() and returns -1.
template <class F>
int guarded(F&& f) {
  try {
    state().message.clear();
    return f();
  } catch (const std::bad_alloc&) {
    state().message = "out of memory: fewer bodies (initial.N)";
  } catch (const std::exception& e) {
    state().message = e.what();
  }
  return -1;
}

void keep(const LabSession& s, const LabFrame& f) {
  auto& a = state().arrays;
  a.clear();
  a["x"] = f.bodies.x, a["v"] = f.bodies.v, a["m"] = f.bodies.m;
  a["exact_v"], a["exact_rho"], a["shock_x"], a["shock_v"], a["shock_mass"];
  if (f.exact) {
    a["exact_v"] = f.exact->v, a["exact_rho"] = f.exact->rho;
    for (const auto& k : f.exact->shocks)
      a["shock_x"].push_back(k.x), a["shock_v"].push_back(k.v), a["shock_mass"].push_back(k.mass);
  }
  a["hull_x"], a["hull_v"], a["hull_m"], a["cluster_x"], a["cluster_v"], a["cluster_m"];
  for (const auto& c : f.hull)
    a["hull_x"].push_back(c.x), a["hull_v"].push_back(c.v), a["hull_m"].push_back(c.m);
  for (const auto& c : f.clusters)
    a["cluster_x"].push_back(c.x), a["cluster_v"].push_back(c.v), a["cluster_m"].push_back(c.m);
  using shockgas::particles::CollisionKind;
  const auto& run = s.run();
  state().values = {{"t", f.t},
                    {"T", f.T},
                    {"collisions", static_cast<double>(run.collisions())},
                    {"inelastic", static_cast<double>(run.count(CollisionKind::inelastic))},
                    {"elastic", static_cast<double>(run.count(CollisionKind::elastic))},
                    {"merges", static_cast<double>(run.count(CollisionKind::merge))},
                    {"dissipated", run.dissipated()},
                    {"mass", shockgas::total_mass(f.bodies)},
                    {"alive", static_cast<double>(run.alive())},
                    {"L", s.length()},
                    {"ring", s.ring() ? 1.0 : 0.0},
                    {"particle_mass", s.particle_mass()},
                    {"N", static_cast<double>(s.bodies())},
                    {"r", s.settings().r},
                    {"delta", s.settings().delta},
                    {"sticky", s.settings().sticky ? 1.0 : 0.0},
                    {"seed", s.settings().seed},
                    {"stop_position", 0.0}};
}

// FNV-1a over the bits of the doubles.
std::uint64_t fnv1a(const double* x, std::size_t n) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < n; ++i) {
    unsigned char bytes[sizeof(double)];
    std::memcpy(bytes, &x[i], sizeof bytes);
    for (unsigned char b : bytes) h = (h ^ b) * 0x100000001b3ULL;
  }
  return h;
}

}  // namespace

extern "C" {

int lab_start(const char* scene, double N, double r, double delta, int sticky, int line, double seed) {
  return guarded([&] {
    shockgas::lab::LabSettings s{scene ? scene : "", N, r, delta, sticky != 0, line != 0, seed};
    auto session = std::make_unique<LabSession>(s);  // the old one stays if this throws
    state().session = std::move(session);
    state().arrays.clear(), state().values.clear();  // until the first lab_advance
    return 0;
  });
}

int lab_advance(double t, double budget, int cells) {
  return guarded([&] {
    if (!state().session) throw std::runtime_error("no run: lab_start first");
    if (!(budget >= 0 && budget <= 0x1p63)) throw std::runtime_error("a collision budget >= 0");
    if (cells < 1) throw std::runtime_error("cells >= 1");
    LabSession& s = *state().session;
    const auto step = s.advance(t, static_cast<std::uint64_t>(budget));
    keep(s, s.frame(static_cast<std::size_t>(cells)));
    state().values["stop_position"] = step.stop.position;
    return step.ended ? 2 : step.reached ? 0 : 1;
  });
}

const double* lab_array(const char* name) {
  const auto it = state().arrays.find(name ? name : "");
  return it == state().arrays.end() ? nullptr : it->second.data();
}

int lab_size(const char* name) {
  const auto it = state().arrays.find(name ? name : "");
  return it == state().arrays.end() ? -1 : static_cast<int>(it->second.size());
}

double lab_value(const char* name) {
  const auto it = state().values.find(name ? name : "");
  return it == state().values.end() ? std::nan("") : it->second;
}

const char* lab_message() { return state().message.c_str(); }

const char* lab_digest() {
  std::string& out = state().digest;
  out.clear();
  char line[160];
  for (const auto& [name, a] : state().arrays) {
    std::snprintf(line, sizeof line, "%s %zu %016" PRIx64 "\n", name.c_str(), a.size(),
                  fnv1a(a.data(), a.size()));
    out += line;
  }
  for (const auto& [name, v] : state().values) {
    std::snprintf(line, sizeof line, "%s 1 %016" PRIx64 "\n", name.c_str(), fnv1a(&v, 1));
    out += line;
  }
  return out.c_str();
}

}  // extern "C"
