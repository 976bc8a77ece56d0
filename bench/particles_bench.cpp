// Whole-process rate and peak memory of the particle engine against the
// straightforward engine (particles_baseline.hpp), and the thread scaling of one
// realization. Every measurement is a process of its own (this program, run again
// as a child), timed from outside: set-up, events, observables and the final
// state included, and its peak memory is the operating system's (wait4).
//
// Reference gas: a ring, L = N, lattice positions, velocities uniform on [-1, 1],
// r = 0.9, delta = 10^-2, the default observables (40 log-spaced samples, cluster
// counting on). The engine streams its final state to a sink (as a file writer
// would) instead of keeping a copy; the baseline records T at the same 40 times.
//
//   particles_bench [--full] [--csv=FILE] [--png=FILE] [--runs=K] [--scaling-t=T] [--max-n=N]
//
// Sizes N = 10^4 ... 10^7 (10^8 with --full), short (t = 10) and long (t = 10^3)
// runs; the baseline up to N = 10^7 short and 10^6 long (10^7 long with --full:
// about 40 minutes). Thread scaling: N = 10^6 to t = 10^3 (10^4 with --full) on
// 1, 2, ... usable cores, K runs each (default 5), alternating. Writes FILE
// (default particles_bench.csv), one row per process, and draws FILE.png with
// plots/plot_particles_bench.py (/usr/bin/python3 with matplotlib). --max-n
// leaves out the larger sizes (and scales the thread runs down to it).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "particles_baseline.hpp"
#include "shockgas/core/cores.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"

namespace {

constexpr double kR = 0.9;
constexpr double kDelta = 1e-2;
constexpr std::size_t kSamples = 40;

shockgas::InitialParams reference_gas(std::size_t n) {
  shockgas::InitialParams ip;
  ip.N = n;
  ip.seed = 2026;
  return ip;
}

// ---- children: one run each, printing "collisions T_final" on stdout ----

int child_engine(std::size_t n, double t_end, std::size_t threads) {
  shockgas::particles::ParticleParams p;
  p.r = kR;
  p.delta = kDelta;
  p.t_end = t_end;
  p.samples = kSamples;
  p.threads = threads;
  double checksum = 0;  // the final state read in chunks, as a writer would
  shockgas::particles::StateSink sink;
  sink.final_state = [&](double, const shockgas::particles::StateReader& s) {
    s.read([&](const double*, const double* v, const double*, std::size_t count) {
      for (std::size_t k = 0; k < count; ++k) checksum += v[k];
    });
  };
  const auto out = shockgas::particles::simulate(reference_gas(n), 0, p, {}, &sink);
  std::printf("%llu %.17g %.3g\n", static_cast<unsigned long long>(out.collisions), out.series.T.back(),
              checksum);
  return 0;
}

// The recorder's sample times: log-spaced from 1 to t_end.
std::vector<double> sample_times(double t_end) {
  std::vector<double> t(kSamples);
  for (std::size_t k = 0; k < kSamples; ++k) t[k] = std::pow(t_end, static_cast<double>(k) / (kSamples - 1));
  t.back() = t_end;
  return t;
}

int child_baseline(std::size_t n, double t_end) {
  shockgas::bench::BaselineEngine engine(shockgas::make_initial_bodies(reference_gas(n)),
                                         static_cast<double>(n), kR, kDelta);
  std::uint64_t collisions = 0;
  double T = 0;
  for (double t : sample_times(t_end)) collisions = engine.run_until(t), T = engine.temperature();
  std::printf("%llu %.17g 0\n", static_cast<unsigned long long>(collisions), T);
  return 0;
}

// ---- the parent: runs children and measures them ----

struct Measured {
  std::string what, engine;
  std::size_t n = 0, threads = 1, run = 0;
  double t_end = 0;
  unsigned long long collisions = 0;
  double T_final = 0, wall = 0, cpu = 0, peak_bytes = 0;
  bool ok = false;
};

// Runs this program with args as a child; wall clock, CPU time and peak memory
// from wait4.
Measured measure(const std::vector<std::string>& args) {
  Measured m;
  int out[2];
  if (pipe(out) != 0) return m;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    close(out[0]);
    close(out[1]);
    std::vector<char*> argv;
    std::string self = "/proc/self/exe";
    argv.push_back(self.data());
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  close(out[1]);
  std::string text;
  char buffer[256];
  for (ssize_t got; (got = read(out[0], buffer, sizeof buffer)) > 0;)
    text.append(buffer, static_cast<std::size_t>(got));
  close(out[0]);
  int status = 0;
  rusage usage{};
  if (pid < 0 || wait4(pid, &status, 0, &usage) != pid) return m;
  m.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto seconds = [](const timeval& tv) {
    return static_cast<double>(tv.tv_sec) + 1e-6 * static_cast<double>(tv.tv_usec);
  };
  m.cpu = seconds(usage.ru_utime) + seconds(usage.ru_stime);
  m.peak_bytes = 1024.0 * static_cast<double>(usage.ru_maxrss);  // Linux: kilobytes
  std::istringstream in(text);
  m.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 && static_cast<bool>(in >> m.collisions >> m.T_final);
  return m;
}

Measured run_child(const std::string& engine, std::size_t n, double t_end, std::size_t threads,
                   std::size_t run, const std::string& what) {
  std::vector<std::string> args = {"--child=" + engine, std::to_string(n), std::to_string(t_end),
                                   std::to_string(threads)};
  Measured m = measure(args);
  m.what = what, m.engine = engine, m.n = n, m.t_end = t_end, m.threads = threads, m.run = run;
  std::fprintf(
      stderr,
      "%-8s %-8s N = %-9zu t = %-6g threads %zu: %s%.3g collisions in %.2f s wall (%.2f M/s), %.0f MiB\n",
      what.c_str(), engine.c_str(), n, t_end, threads, m.ok ? "" : "FAILED ", double(m.collisions), m.wall,
      m.wall > 0 ? double(m.collisions) / m.wall / 1e6 : 0.0, m.peak_bytes / (1 << 20));
  return m;
}

void write_csv(const std::string& path, const std::vector<Measured>& rows) {
  std::ofstream out(path);
  out << "case,engine,N,t_end,threads,run,ok,collisions,T_final,wall_s,cpu_s,peak_bytes,bytes_per_particle,"
         "rate_wall_per_s,rate_cpu_per_s\n";
  for (const Measured& m : rows) {
    char line[512];
    std::snprintf(line, sizeof line, "%s,%s,%zu,%g,%zu,%zu,%d,%llu,%.17g,%.4f,%.4f,%.0f,%.2f,%.6g,%.6g\n",
                  m.what.c_str(), m.engine.c_str(), m.n, m.t_end, m.threads, m.run, m.ok ? 1 : 0,
                  m.collisions, m.T_final, m.wall, m.cpu, m.peak_bytes,
                  m.peak_bytes / static_cast<double>(m.n), m.wall > 0 ? double(m.collisions) / m.wall : 0.0,
                  m.cpu > 0 ? double(m.collisions) / m.cpu : 0.0);
    out << line;
  }
}

struct Options {
  bool full = false;
  std::string csv = "particles_bench.csv", png;
  std::size_t runs = 5;
  double scaling_t = 0;   // 0: 10^3, or 10^4 with --full
  std::size_t max_n = 0;  // 0: no limit
};

int parent(const Options& o) {
  std::vector<Measured> rows;
  std::vector<std::size_t> sizes = {10'000, 100'000, 1'000'000, 10'000'000};
  if (o.full) sizes.push_back(100'000'000);
  if (o.max_n > 0)
    sizes.erase(std::remove_if(sizes.begin(), sizes.end(), [&](std::size_t n) { return n > o.max_n; }),
                sizes.end());
  const std::size_t scaling_n = o.max_n > 0 ? std::min<std::size_t>(o.max_n, 1'000'000) : 1'000'000;
  for (double t_end : {10.0, 1000.0}) {
    for (std::size_t n : sizes) {
      const char* what = t_end < 100 ? "short" : "long";
      rows.push_back(run_child("engine", n, t_end, 1, 0, what));
      const bool baseline = n <= 10'000'000 && (t_end < 100 || n <= 1'000'000 || o.full);
      if (baseline) rows.push_back(run_child("baseline", n, t_end, 1, 0, what));
      write_csv(o.csv, rows);
    }
  }
  // One realization on 1, 2, 4, ... threads up to the usable cores, alternating.
  std::vector<std::size_t> threads;
  for (std::size_t k = 1; k < shockgas::usable_cores(); k *= 2) threads.push_back(k);
  threads.push_back(shockgas::usable_cores());
  const double t_scaling = o.scaling_t > 0 ? o.scaling_t : (o.full ? 1e4 : 1e3);
  for (std::size_t run = 0; run < o.runs; ++run)
    for (std::size_t k : threads)
      rows.push_back(run_child("engine", scaling_n, t_scaling, k, run, "scaling"));
  write_csv(o.csv, rows);
  std::cout << "wrote " << o.csv << '\n';
  const std::string png = o.png.empty() ? o.csv.substr(0, o.csv.rfind('.')) + ".png" : o.png;
  const std::string plot = std::string("/usr/bin/python3 ") + SHOCKGAS_SOURCE_DIR +
                           "/plots/plot_particles_bench.py '" + o.csv + "' '" + png + "'";
  if (std::system(plot.c_str()) != 0)
    std::cerr << "no chart (needs /usr/bin/python3 with matplotlib): " << plot << '\n';
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  std::string child;
  std::vector<std::string> rest;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--full") {
      o.full = true;
    } else if (a.rfind("--csv=", 0) == 0) {
      o.csv = a.substr(6);
    } else if (a.rfind("--png=", 0) == 0) {
      o.png = a.substr(6);
    } else if (a.rfind("--runs=", 0) == 0) {
      o.runs = std::stoul(a.substr(7));
    } else if (a.rfind("--scaling-t=", 0) == 0) {
      o.scaling_t = std::stod(a.substr(12));
    } else if (a.rfind("--max-n=", 0) == 0) {
      o.max_n = std::stoull(a.substr(8));
    } else if (a.rfind("--child=", 0) == 0) {
      child = a.substr(8);
    } else if (!child.empty()) {
      rest.push_back(a);
    } else {
      std::cerr << "usage: particles_bench [--full] [--csv=FILE] [--png=FILE] [--runs=K] [--scaling-t=T] "
                   "[--max-n=N]\n";
      return 2;
    }
  }
  if (child.empty()) return parent(o);
  if (rest.size() != 3) return 2;
  const std::size_t n = std::stoull(rest[0]);
  const double t_end = std::stod(rest[1]);
  if (child == "engine") return child_engine(n, t_end, std::stoul(rest[2]));
  if (child == "baseline") return child_baseline(n, t_end);
  return 2;
}
