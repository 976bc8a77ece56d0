#!/usr/bin/python3
"""Fig. 2 from the kept runs (data/paper-runs/fig2, docs/paper.md): does T(t)
depend on the threshold delta or on what happens below it?

    scripts/paper/plot_fig2_runs.py data/paper-runs/fig2 --out docs/img/paper

Each directory under the root holds T.csv and summary.json of one run
(scripts/paper/collect_paper_run.py): the variants of fig2.toml (one realization each,
r = 0.9), and the exact hull (r = 0) of fig1-hull.toml with t_end = 10^6 and the
same seed, whose realization 0 is the same initial state as the variants'.
Draws fig2-paper-size.png:
  left   T t^(2/3) against t: every variant, the exact sticky gas of the same
         initial state (realization 0 of the hull), the exact late-time value
         0.2129 (D = 1/3), and t_valid = delta^-3 where the runs reach it;
  right  T / T_hull - 1 against t from T_START on (past the crossover to the
         sticky regime, t_stick = 89), T_hull that of the same initial state: the
         difference is the rule's, not another sample of the noise. A run of
         several realizations shows the mean over the realizations it shares with
         the hull and its standard error (shaded). The grey band is one standard
         deviation of T_i / <T> - 1 over the hull's realizations: how far one
         realization of another initial state would stray.
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
T_START = 100.0
STYLE = {("elastic", 0.01): ("C0", "-"), ("sticky", 0.01): ("C1", "--"),
         ("elastic", 0.001): ("C2", "-"), ("sticky", 0.001): ("C3", "--")}


def load(d):
    """One kept run: its parameters, T(t) of realization 0 and every realization's T."""
    s = run_files.read_summary(d)
    rows = run_files.read_series(d)
    columns = run_files.realization_columns(rows)
    p = s["particles"]
    rule = "hull" if p["solver"] == "hull" else (
        "sticky" if any(o.endswith("subthreshold=sticky") for o in s["overrides"]) else "elastic")
    return {"name": os.path.basename(os.path.normpath(d)), "rule": rule, "delta": p["delta"], "N": s["initial"]["N"],
            "seed": s["initial"]["seed"], "realizations": p["realizations"], "collisions": p["collisions"],
            "T": [(r["t"], r[columns[0]] if columns else r["T"]) for r in rows],
            "each": [[r[c] for c in columns] for r in rows]}


def label(run):
    if run["rule"] == "hull":
        return "exact sticky gas r = 0, the same initial state"
    return "delta = %g, %s below it" % (run["delta"], run["rule"])


def interpolate(series, t):
    """T at t, linear in ln T against ln t between samples; None outside them."""
    for (t0, T0), (t1, T1) in zip(series, series[1:]):
        if t0 <= t <= t1:
            w = math.log(t / t0) / math.log(t1 / t0)
            return math.exp((1 - w) * math.log(T0) + w * math.log(T1))
    return None


def paired(run, hull):
    """(t, mean, standard error) over the realizations both runs hold of
    T_i / T_hull,i - 1 (realization i of both starts from the same state), t >= T_START."""
    n = min(len(run["each"][0]), len(hull["each"][0]))
    hull_i = [[(t, each[i]) for (t, _), each in zip(hull["T"], hull["each"])] for i in range(n)]
    out = []
    for (t, _), each in zip(run["T"], run["each"]):
        ref = [interpolate(h, t) for h in hull_i]
        if t < T_START or None in ref:
            continue
        d = [each[i] / ref[i] - 1 for i in range(n)]
        mean = sum(d) / n
        error = math.sqrt(sum((x - mean) ** 2 for x in d) / (n - 1) / n) if n >= 2 else math.nan
        out.append((t, mean, error))
    return out


def scatter(hull):
    """t and the standard deviation over realizations of T_i / <T> - 1."""
    out = []
    for (t, _), each in zip(hull["T"], hull["each"]):
        mean = sum(each) / len(each)
        out.append((t, math.sqrt(sum((x / mean - 1) ** 2 for x in each) / (len(each) - 1))))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("root")
    ap.add_argument("--out", default=".")
    a = ap.parse_args()
    runs = [load(d) for d in run_files.run_dirs(a.root)]
    hull = next(r for r in runs if r["rule"] == "hull")
    variants = [r for r in runs if r is not hull]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11.5, 4.6))
    left.plot([t for t, _ in hull["T"]], [T * t ** (2 / 3) for t, T in hull["T"]], color="0.3", lw=2.2,
              alpha=0.6, label=label(hull))
    band = [(t, s) for t, s in scatter(hull) if t >= T_START]
    right.fill_between([t for t, _ in band], [-s for _, s in band], [s for _, s in band], color="0.85",
                       label="one realization of another state (1 s.d.)")
    # Runs of one rule and delta share realization 0 (same N and seed): the left
    # panel draws it once, from the run that reaches furthest; the right panel the
    # run with the most realizations paired with the hull.
    groups = {}
    for run in variants:
        groups.setdefault((run["rule"], run["delta"], run["N"], run["seed"]), []).append(run)
    for key in sorted(groups, key=lambda k: (-k[1], k[0])):
        group = groups[key]
        run = max(group, key=lambda r: (r["T"][-1][0], r["realizations"]))
        colour, ls = STYLE.get((run["rule"], run["delta"]), ("C7", ":"))
        left.plot([t for t, _ in run["T"]], [T * t ** (2 / 3) for t, T in run["T"]], ls, color=colour, lw=1.2,
                  label="%s (N = %.0e)" % (label(run), run["N"]))
        run = max(group, key=lambda r: (r["realizations"], r["T"][-1][0]))
        if (run["N"], run["seed"]) == (hull["N"], hull["seed"]):
            rel = paired(run, hull)
            n = min(len(run["each"][0]), len(hull["each"][0]))
            right.plot([t for t, _, _ in rel], [y for _, y, _ in rel], ls, color=colour, lw=1.2,
                       label="%s, %d paired" % (label(run), n) if n > 1 else label(run))
            if n > 1:
                right.fill_between([t for t, _, _ in rel], [y - e for _, y, e in rel], [y + e for _, y, e in rel],
                                   color=colour, alpha=0.25, lw=0)
    left.axhline(EXACT_T_T23, color="k", ls="--", lw=1, label="exact late-time law: 0.2129")
    t_max = max(t for r in runs for t, _ in r["T"]) * 1.5
    for delta in sorted({r["delta"] for r in variants if r["delta"] ** -3 <= t_max}):
        for ax in (left, right):
            ax.axvline(delta ** -3, color="0.5", ls=":", lw=1)
        left.text(delta ** -3, 0.5, "t_valid = delta^-3 = %g " % delta ** -3, fontsize=7, rotation=90,
                  ha="right", va="center", transform=left.get_xaxis_transform())
    for ax, t_min in ((left, 1), (right, T_START)):
        ax.set_xscale("log")
        ax.set_xlim(t_min, t_max)
        ax.set_xlabel(axis_label("time $t$", "time"))
    left.set_yscale("log")
    left.set_ylabel(axis_label("$T\\,t^{2/3}$", run_files.UNIT_T_SCALED))
    left.set_title("r = 0.9, N = %.0e, realization 0" % hull["N"])
    left.legend(fontsize=7)
    right.axhline(0, color="k", lw=0.8)
    right.set_ylabel(axis_label("$T / T$(exact sticky gas, same state) $- 1$", "1"))
    right.set_title("against the r = 0 gas of the same initial state")
    right.legend(fontsize=7)
    fig.tight_layout()
    os.makedirs(a.out, exist_ok=True)
    save(fig, os.path.join(a.out, "fig2-paper-size.png"),
         f"{run_files.SERIES}, {run_files.SUMMARY} of the kept runs in {a.root}")


if __name__ == "__main__":
    main()
