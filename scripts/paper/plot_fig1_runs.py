#!/usr/bin/python3
"""Fig. 1 at the paper's size from the kept runs (data/paper-runs/fig1, docs/paper.md).

    scripts/paper/plot_fig1_runs.py data/paper-runs/fig1 --out docs/img/paper

Reads each run's T.csv and summary.json (scripts/paper/collect_paper_run.py) and draws
two pictures, each of two panels:
  left   T t^(2/3) against t, with the standard error over realizations, and the
         exact continuum value of the sticky gas 0.17571 (4D)^(2/3) = 0.2129 (D = 1/3);
  right  the exponent of T(t) fitted on each decade [t, 10 t], with its jackknife
         error over realizations (analysis.T_exponent_windows), and -2/3.
fig1-paper-size.png       r = 0: the event engine and the exact hull;
fig1-rpos-paper-size.png  r = 0, 0.5, 0.9, 0.99 by the event engine, the same ten
                          initial states (drawn when those runs are kept).
A run that is not kept is left out of its picture.
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plots"))
from shockplot import run_files  # noqa: E402
from shockplot.common import label as axis_label  # noqa: E402
from shockplot.saving import save  # noqa: E402

EXACT_T_T23 = 0.2128531785  # shockgas/compare/cluster_velocity_law.hpp, D = 1/3
R0_RUNS = [  # directory, legend, colour
    ("hull-r0-R1000", "exact hull, 1000 x N = 10^6", "C0"),
    ("hull-r0-R10", "exact hull, 10 x N = 10^6 (realizations 0-9)", "C1"),
    ("r0", "event engine r = 0, 10 x N = 10^6 (same 10)", "C3"),
]
RESTITUTION_RUNS = [
    ("r0", "r = 0", "C3"),
    ("events-r0.5-R10", "r = 0.5", "C2"),
    ("events-r0.9-R10", "r = 0.9", "C0"),
    ("events-r0.99-R10", "r = 0.99", "C4"),
]


def draw(root, runs, title, out_dir, file_name, log_y=False):
    kept = [(name, label, colour) for name, label, colour in runs if os.path.isdir(os.path.join(root, name))]
    if len(kept) < 2:
        return
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.4))
    for k, (name, label, colour) in enumerate(kept):
        d = os.path.join(root, name)
        series = [(t, T, e) for t, T, e in run_files.T_series(d) if t >= 10]
        scale = [t ** (2.0 / 3.0) for t, _, _ in series]
        left.errorbar([t for t, _, _ in series], [T * s for (_, T, _), s in zip(series, scale)],
                      yerr=[e * s for (_, _, e), s in zip(series, scale)], fmt="o-", ms=2.5, lw=0.8,
                      color=colour, label=label)
        windows = [w for w in run_files.read_summary(d, first_variant=True)["analysis"]["T_exponent_windows"]
                   if abs(w["t_max"] / w["t_min"] - 10) < 1e-6]
        shift = 1 + 0.06 * (k - (len(kept) - 1) / 2)
        right.errorbar([math.sqrt(w["t_min"] * w["t_max"]) * shift for w in windows],
                       [w["exponent"] for w in windows], yerr=[w["jackknife_error"] for w in windows],
                       fmt="o", ms=4, capsize=2, color=colour, label=label)
    left.axhline(EXACT_T_T23, color="k", ls="--", lw=1, label="exact continuum law (r = 0): 0.2129")
    left.set_xscale("log")
    if log_y:
        left.set_yscale("log")
    left.set_xlabel(axis_label("time $t$", "time"))
    left.set_ylabel(axis_label("$T\\,t^{2/3}$", run_files.UNIT_T_SCALED))
    left.set_title(title + ": T t^(2/3), error over realizations")
    left.legend(fontsize=7)
    right.axhline(-2.0 / 3.0, color="k", ls="--", lw=1, label="-2/3")
    right.set_xscale("log")
    right.set_xlabel(axis_label("time $t$, centre of the decade fitted", "time"))
    right.set_ylabel(axis_label("exponent of $T(t)$ fitted on the decade", "1"))
    right.set_title("exponent per decade, jackknife error over realizations")
    right.legend(fontsize=7)
    fig.tight_layout()
    save(fig, os.path.join(out_dir, file_name), f"{run_files.SERIES}, {run_files.SUMMARY} of the kept runs in {root}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("root")
    ap.add_argument("--out", default=".")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    draw(a.root, R0_RUNS, "r = 0", a.out, "fig1-paper-size.png")
    draw(a.root, RESTITUTION_RUNS, "10 x N = 10^6", a.out, "fig1-rpos-paper-size.png", log_y=True)


if __name__ == "__main__":
    main()
