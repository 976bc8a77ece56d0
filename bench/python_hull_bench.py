"""The cost of calling the exact hull from Python: shockgas.hull on 10^6 bodies
against the same call from C++ (bench/hull_call_bench.cpp: sticky_clusters_ring).

Both time process CPU (the machine may be shared: wall time would measure the
neighbours) on the same bodies (initial.N = 10^6, initial.seed = 2026, a
lattice ring, velocities uniform on [-1, 1]) at t = 1 (most bodies still apart:
the output is large) and t = 1000 (few clusters). Rounds alternate C++ and
Python; the medians of all rounds and their ratio are printed.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_hull_bench.py [--build build] [--rounds 5]
"""

import argparse
import json
import pathlib
import statistics
import subprocess
import time

import shockgas

N, SEED, TIMES = 10**6, 2026, (1, 1000)


def cpp_round(build, repetitions):
    """Median CPU ms per call of each t, from Google Benchmark's JSON."""
    out = subprocess.run([str(build / "bench" / "hull_call_bench"), "--benchmark_format=json",
                          f"--benchmark_repetitions={repetitions}", "--benchmark_report_aggregates_only=true"],
                         capture_output=True, text=True, check=True).stdout
    medians = {}
    for b in json.loads(out)["benchmarks"]:
        if b.get("aggregate_name") == "median":
            t = int(b["run_name"].split("t:")[1].split("/")[0])
            medians[t] = b["cpu_time"]  # Unit: ms (the benchmark's own unit)
    return medians


def python_round(bodies, repetitions):
    """Median CPU ms per call of shockgas.hull at each t."""
    medians = {}
    for t in TIMES:
        times = []
        for _ in range(repetitions):
            start = time.process_time()
            clusters = shockgas.hull(bodies.x, bodies.v, bodies.m, float(t))
            times.append(1e3 * (time.process_time() - start))
            del clusters
        medians[t] = statistics.median(times)
    return medians


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", type=pathlib.Path)
    parser.add_argument("--rounds", default=5, type=int)
    parser.add_argument("--repetitions", default=7, type=int)
    args = parser.parse_args()
    bodies = shockgas.particles.initial_bodies(N=N, seed=SEED)
    cpp, py = {t: [] for t in TIMES}, {t: [] for t in TIMES}
    for k in range(args.rounds):
        c, p = cpp_round(args.build, args.repetitions), python_round(bodies, args.repetitions)
        for t in TIMES:
            cpp[t].append(c[t])
            py[t].append(p[t])
        print(f"round {k + 1}: " + ", ".join(f"t = {t}: C++ {c[t]:.2f} ms, Python {p[t]:.2f} ms" for t in TIMES))
    for t in TIMES:
        c, p = statistics.median(cpp[t]), statistics.median(py[t])
        print(f"t = {t}: median C++ {c:.2f} ms, Python {p:.2f} ms per call of {N} bodies; "
              f"Python / C++ = {p / c:.3f}")


if __name__ == "__main__":
    main()
