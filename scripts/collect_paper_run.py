#!/usr/bin/python3
"""Keep what docs/paper.md needs of a run, so that the page can be redrawn
without re-running it (data/paper-runs/).

    scripts/collect_paper_run.py RUN_DIR DEST [--label NAME]

For every directory under RUN_DIR that holds a summary.json of a particle run
(a scene, or each variant of a sweep), writes under DEST/<its name>/:
  summary.json   as written by the run;
  T.csv          t, T (ensemble mean), T_stderr, and one column per
                 realization when there are at most 100 of them;
  histogram.csv  t, z, density (ensemble mean), when the run kept a histogram,
                 its standard error over realizations (density_stderr) when the run
                 kept every realization's histogram, and exact: the exact
                 mass-weighted law of the sticky gas averaged over the bin, when
                 the run wrote it.
Leaves out the states (realization 0's final state is megabytes at N = 10^6).
"""
import argparse
import csv
import json
import os
import shutil

import h5py
import numpy as np


def particle_runs(root):
    for d, _, files in sorted(os.walk(root)):
        if "summary.json" in files and "result.h5" in files:
            with open(os.path.join(d, "summary.json")) as f:
                if "particles" in json.load(f):
                    yield d


def write_series(h5, path):
    t = h5["particles/t"][:]
    cols = {"t": t, "T": h5["particles/T"][:], "T_stderr": h5["particles/T_stderr"][:]}
    if "particles/realizations/T" in h5:
        rows = h5["particles/realizations/T"][:]
        if rows.shape[0] <= 100:
            for i, row in enumerate(rows):
                cols["T_%d" % i] = row
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols.keys())
        for k in range(len(t)):
            w.writerow([repr(float(c[k])) if np.isfinite(c[k]) else "" for c in cols.values()])


def write_histogram(h5, path):
    if "particles/histogram/density" not in h5:
        return
    z, t = h5["particles/histogram/z"][:], h5["particles/histogram/t"][:]
    density = h5["particles/histogram/density"][:]
    columns = {}
    if "particles/realizations/histogram_density" in h5:
        rows = h5["particles/realizations/histogram_density"][:]
        if rows.shape[0] >= 2:
            per = rows.reshape(rows.shape[0], len(t), len(z))
            columns["density_stderr"] = lambda i, j: per[:, i, j].std(ddof=1) / np.sqrt(per.shape[0])
    if "particles/histogram/exact" in h5:
        exact = h5["particles/histogram/exact"][:]
        columns["exact"] = lambda i, j: exact[j]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["t", "z", "density"] + list(columns))
        for i, ti in enumerate(t):
            for j, zj in enumerate(z):
                row = [ti, zj, density[i, j]] + [value(i, j) for value in columns.values()]
                w.writerow([repr(float(x)) for x in row])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("dest")
    ap.add_argument("--label", help="name for a single run (default: its directory name)")
    a = ap.parse_args()
    for d in particle_runs(a.run_dir):
        name = a.label if a.label else os.path.basename(os.path.normpath(d))
        out = os.path.join(a.dest, name)
        os.makedirs(out, exist_ok=True)
        shutil.copy(os.path.join(d, "summary.json"), out)
        with h5py.File(os.path.join(d, "result.h5"), "r") as h5:
            write_series(h5, os.path.join(out, "T.csv"))
            write_histogram(h5, os.path.join(out, "histogram.csv"))
        print("kept", d, "->", out)


if __name__ == "__main__":
    main()
