#!/usr/bin/python3
"""Keep what docs/paper.md needs of a run, so that the page can be redrawn
without re-running it (data/paper-runs/).

    scripts/paper/collect_paper_run.py RUN_DIR DEST [--label NAME]

For every directory under RUN_DIR that holds a summary.json of a particle run
(a scene, or each variant of a sweep), writes under DEST/<its name>/ its
summary.json, T.csv and histogram.csv (the format: plots/shockplot/run_files.py).
Leaves out the states (realization 0's final state is megabytes at N = 10^6).
"""
import argparse
import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plots"))
from shockplot import run_files  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("dest")
    ap.add_argument("--label", help="name for a single run (default: its directory name)")
    a = ap.parse_args()
    for d, _ in run_files.particle_runs(a.run_dir):
        name = a.label if a.label else os.path.basename(os.path.normpath(d))
        out = os.path.join(a.dest, name)
        os.makedirs(out, exist_ok=True)
        shutil.copy(os.path.join(d, run_files.SUMMARY), out)
        with run_files.open_result(d) as h5:
            run_files.write_series(h5, os.path.join(out, run_files.SERIES))
            run_files.write_histogram(h5, os.path.join(out, run_files.HISTOGRAM))
        print("kept", d, "->", out)


if __name__ == "__main__":
    main()
