#!/usr/bin/python3
"""Keep what docs/paper.md needs of a run, so that the page can be redrawn
without re-running it (data/paper-runs/).

    scripts/collect_paper_run.py RUN_DIR DEST [--label NAME]

For every directory under RUN_DIR that holds a summary.json of a particle run
(a scene, or each variant of a sweep), writes under DEST/<its name>/ its
summary.json, T.csv and histogram.csv (the format: scripts/shockplot/kept_runs.py).
Leaves out the states (realization 0's final state is megabytes at N = 10^6).
"""
import argparse
import json
import os
import shutil

import h5py

from shockplot import kept_runs


def particle_runs(root):
    for d, _, files in sorted(os.walk(root)):
        if "summary.json" in files and "result.h5" in files:
            with open(os.path.join(d, "summary.json")) as f:
                if "particles" in json.load(f):
                    yield d


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
        shutil.copy(os.path.join(d, kept_runs.SUMMARY), out)
        with h5py.File(os.path.join(d, "result.h5"), "r") as h5:
            kept_runs.write_series(h5, os.path.join(out, kept_runs.SERIES))
            kept_runs.write_histogram(h5, os.path.join(out, kept_runs.HISTOGRAM))
        print("kept", d, "->", out)


if __name__ == "__main__":
    main()
