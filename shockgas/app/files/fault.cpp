#include "shockgas/app/files/fault.hpp"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <string>

namespace shockgas::app {

namespace {

struct FaultSpec {
  std::string point;  // empty: none
  long hit = 1;       // the pass that acts
  int signal = SIGKILL;
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// "point", "point:n", each optionally followed by ":stop"; the count follows
// the last ':' when it is a number ("write:result.h5:3").
FaultSpec parse(const char* env) {
  FaultSpec f;
  if (!env) return f;
  std::string spec = env;
  if (ends_with(spec, ":stop")) {
    f.signal = SIGSTOP;
    spec.resize(spec.size() - 5);
  }
  const auto colon = spec.rfind(':');
  if (colon != std::string::npos && colon + 1 < spec.size() &&
      spec.find_first_not_of("0123456789", colon + 1) == std::string::npos) {
    f.hit = std::atol(spec.c_str() + colon + 1);
    spec.resize(colon);
  }
  f.point = spec;
  return f;
}

std::atomic<long> g_passes{0};

}  // namespace

void fault_point(std::string_view point) {
  static const FaultSpec spec = parse(std::getenv("SHOCKGAS_FAULT"));
  if (spec.point.empty() || point != spec.point) return;
  if (++g_passes == spec.hit || (spec.signal == SIGKILL && g_passes > spec.hit)) std::raise(spec.signal);
}

}  // namespace shockgas::app
