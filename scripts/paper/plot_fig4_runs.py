#!/usr/bin/python3
"""Fig. 4 from the kept runs (data/paper-runs/fig4, docs/paper.md): the scaled
velocity distribution Phi(z), z = (v - <v>) t^(1/3), of r = 0, 0.5, 0.9 at the
late sample times, over the exact mass-weighted law of the sticky gas.

    scripts/paper/plot_fig4_runs.py data/paper-runs/fig4 --out docs/img/paper [--runs events-r0-R50 ...]

Each run directory holds histogram.csv (scripts/paper/collect_paper_run.py: t, z,
density, and when kept density_stderr and exact). Draws fig4-paper-size.png:
  left   Phi(z) on a log scale, every run at every t >= --t-min, and the exact
         law's bin means (black, dashed);
  right  Phi / exact - 1 with the standard error over realizations, over the
         bins where the exact law is above 10^-2 (the tails are the left
         panel's, and the tail study's).
"""
import argparse
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plots"))
from shockplot import run_files  # noqa: E402
from shockplot.common import label as axis_label  # noqa: E402
from shockplot.saving import save  # noqa: E402

COLOURS = {0.0: "C3", 0.5: "C2", 0.9: "C0"}
MARKERS = ["o", "s", "^", "v", "D"]


def read(d):
    s = run_files.read_summary(d)
    return s["particles"]["r"], s["particles"]["realizations"], s["initial"]["N"], run_files.read_histogram(d)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("root")
    ap.add_argument("--out", default=".")
    ap.add_argument("--runs", nargs="*", help="run directories under ROOT (default: every events-*-R50)")
    ap.add_argument("--t-min", type=float, default=1e3)
    a = ap.parse_args()
    names = a.runs or [os.path.basename(d) for d in sorted(glob.glob(os.path.join(a.root, "events-*-R50")))]
    runs = sorted((read(os.path.join(a.root, n)) for n in names), key=lambda run: run[0])
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6))
    exact = None
    for r, realizations, N, rows in runs:
        times = [t for t in sorted(rows) if t >= a.t_min * (1 - 1e-9)]
        for k, t in enumerate(times):
            pts = rows[t]
            style = dict(color=COLOURS.get(r, "C7"), marker=MARKERS[k % len(MARKERS)], ms=3, lw=0.6)
            label = "r = %g, t = %g" % (r, t)
            shown = [p for p in pts if p["density"] > 0]
            left.plot([p["z"] for p in shown], [p["density"] for p in shown], **style, label=label)
            if "exact" in pts[0]:
                exact = exact or [(p["z"], p["exact"]) for p in pts]
                core = [p for p in pts if p["exact"] > 1e-2]
                right.errorbar([p["z"] + 0.01 * (k - 1) for p in core], [p["density"] / p["exact"] - 1 for p in core],
                               yerr=[p.get("density_stderr", 0) / p["exact"] for p in core], ls="-", capsize=1,
                               elinewidth=0.6, **style, label=label)
    if exact:
        left.plot([z for z, _ in exact], [e for _, e in exact], "k--", lw=1.2, label="exact sticky gas (r = 0), bin means")
        right.axhline(0, color="k", ls="--", lw=1.2, label="exact sticky gas (r = 0)")
    sizes = sorted({"%d x N = %.0e" % (R, N) for _, R, N, _ in runs})
    left.set_yscale("log")
    left.set_ylim(bottom=1e-6)
    z_label = axis_label(r"$z = (v - \langle v\rangle)\,t^{1/3}$", "length/time^(2/3)")
    left.set_xlabel(z_label)
    left.set_ylabel(axis_label(r"$\Phi(z)$, mass weighted", "time^(2/3)/length"))
    left.set_title("Fig. 4: %s" % ", ".join(sizes))
    left.legend(fontsize=6, ncol=2)
    right.set_xlabel(z_label)
    right.set_ylabel(axis_label(r"$\Phi$ / exact $- 1$", "1"))
    right.set_title("against the exact law, standard error over realizations")
    right.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    os.makedirs(a.out, exist_ok=True)
    save(fig, os.path.join(a.out, "fig4-paper-size.png"),
         f"{run_files.HISTOGRAM}, {run_files.SUMMARY} of the kept runs in {a.root}")


if __name__ == "__main__":
    main()
