#!/usr/bin/python3
"""The numbers docs/paper.md quotes for Figs. 1, 2 and 4 at the paper's size,
as Markdown tables, from the kept runs (data/paper-runs/) alone.

    scripts/paper/paper_tables.py data/paper-runs

fig1/  each run's exponent of T(t) on the windows docs/paper.md uses, with its
       jackknife error over realizations (analysis.T_exponent_windows), T t^(2/3)
       late, and the crossover times t_dissip, t_stick beside 1/eps, eps^(-3/2);
fig2/  each run's least-squares exponent per decade (one realization: no error
       over realizations; the exact hull's realizations give the scatter of one
       realization) and its T against that of the exact sticky gas (r = 0) of the
       same initial state (realization 0 of the hull);
fig4/  collapse*.json (scripts/paper/fig4_collapse.py): the L1 distance of the scaled
       distributions over t, over r and over both, its jackknife error and the
       distance noise alone would give.
A directory that is missing is skipped.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plots"))
import plot_fig2_runs  # noqa: E402
from shockplot.run_files import T_series, read_comparisons, read_summary, run_dirs  # noqa: E402

WINDOWS = [(1e2, 1e4), (1e3, 1e5), (1e4, 1e5)]


def nearest(rows, t):
    return min(rows, key=lambda row: abs(math.log(row[0] / t)))


def pm(value, error, digits=4):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "–"
    if error is None or math.isnan(error):
        return "%.*f" % (digits, value)
    return "%.*f ± %.*f" % (digits, value, digits, error)


def window(s, lo, hi):
    for w in s["analysis"].get("T_exponent_windows", []):
        if math.isclose(w["t_min"], lo) and math.isclose(w["t_max"], hi):
            return pm(w["exponent"], w["jackknife_error"])
    return "–"


def fig1(root):
    print("| run | r | N × realizations | " + " | ".join("exponent on [%g, %g]" % w for w in WINDOWS)
          + " | T t^(2/3) at t ≈ 10⁴ | at t ≈ 10⁵ | t_dissip (1/ε) | t_stick (ε^(−3/2)) |")
    print("|---" * (7 + len(WINDOWS)) + "|")
    for d in run_dirs(root):
        s = read_summary(d)
        a, p = s["analysis"], s["particles"]
        rows = T_series(d)
        late = [pm(T * t ** (2 / 3), e * t ** (2 / 3), 4) if abs(math.log(t / target)) < 0.15 else "–"
                for target in (1e4, 1e5) for t, T, e in [nearest(rows, target)]]
        cross = ["%s (%.0f)" % (pm(a.get(k), a.get(k + "_error"), 0), a[k + "_theory"]) if a.get(k) else "–"
                 for k in ("t_dissip", "t_stick")]
        print("| `%s` | %g | %d × %.0e | %s | %s | %s |" % (
            os.path.basename(d), p["r"], p["realizations"], s["initial"]["N"],
            " | ".join(window(s, *w) for w in WINDOWS), " | ".join(late), " | ".join(cross)))


def decade_slope(rows, lo):
    pts = [(math.log(t), math.log(T)) for t, T, _ in rows if lo * (1 - 1e-9) <= t <= 10 * lo * (1 + 1e-9)]
    if len(pts) < 3 or pts[-1][0] - pts[0][0] < 0.9 * math.log(10):
        return None
    mx, my = sum(x for x, _ in pts) / len(pts), sum(y for _, y in pts) / len(pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)


def fig2_exponent(run, summary_of_run, lo):
    """The decade's exponent: jackknife over realizations when there are several,
    least squares on the one realization otherwise."""
    if run["realizations"] >= 2:
        return window(summary_of_run, lo, 10 * lo)
    slope = decade_slope([(t, T, 0.0) for t, T in run["T"]], lo)
    return "%.3f" % slope if slope is not None else "–"


def single_realization_spread(run, lo):
    slopes = [decade_slope([(t, each[i], 0.0) for (t, _), each in zip(run["T"], run["each"])], lo)
              for i in range(len(run["each"][0]))]
    slopes = [x for x in slopes if x is not None]
    if len(slopes) < 2:
        return ""
    mean = sum(slopes) / len(slopes)
    return " (one: ± %.3f)" % math.sqrt(sum((x - mean) ** 2 for x in slopes) / (len(slopes) - 1))


def fig2(root):
    dirs = run_dirs(root)
    runs = [plot_fig2_runs.load(d) for d in dirs]
    hull = next((r for r in runs if r["rule"] == "hull"), None)
    decades = [1e2, 1e3, 1e4, 1e5]
    print("| run | rule | N × realizations, t_end | collisions (merges for the hull) | "
          + " | ".join("exponent on [%g, %g]" % (t, 10 * t) for t in decades)
          + " | T / T_hull − 1 at t ≈ 10³, 10⁴, 10⁵, 10⁶ (paired) |")
    print("|---" * (5 + len(decades)) + "|")
    for d, run in zip(dirs, runs):
        exponents = [fig2_exponent(run, read_summary(d), lo) + (single_realization_spread(run, lo) if run is hull else "")
                     for lo in decades]
        rel = ["–"] * 4
        if hull and run is not hull and (run["N"], run["seed"]) == (hull["N"], hull["seed"]):
            points = plot_fig2_runs.paired(run, hull)
            for k, t in enumerate((1e3, 1e4, 1e5, 1e6)):
                near = min(points, key=lambda p: abs(math.log(p[0] / t)), default=None)
                if near and abs(math.log(near[0] / t)) < 0.15:
                    rel[k] = "%+.3f" % near[1] + (" ± %.3f" % near[2] if not math.isnan(near[2]) else "")
        print("| `%s` | %s | %.0e × %d, %g | %.3g | %s | %s |" % (
            run["name"], plot_fig2_runs.label(run), run["N"], run["realizations"], run["T"][-1][0],
            run["collisions"], " | ".join(exponents), ", ".join(rel)))


def fig4(root):
    for name, c in read_comparisons(root):
        print("`%s`: %d × N = %.0e, r = %s, t = %s, bins of %.2f in z" % (
            name, c["realizations"], c["N"], ", ".join("%g" % r for r in c["r"]),
            ", ".join("%g" % t for t in c["t"]), c["bin_width"]))
        print()
        print("| distributions compared | pairs | L1 distance | noise floor |")
        print("|---|---|---|---|")
        for g in c["groups"]:
            what = {"over t": "r = %g, every t" % g.get("r", 0), "over r": "t = %g, every r" % g.get("t", 0),
                    "all": "every r and t"}[g["kind"]]
            print("| %s | %d | %s | %.3f |" % (what, g["pairs"], pm(g["distance"], g["error"], 3), g["noise_floor"]))
        print()
        print("| t | r | r′ | L1 distance | noise floor | χ² / bins |")
        print("|---|---|---|---|---|---|")
        for p in c["pairs"]:
            print("| %g | %g | %g | %s | %.3f | %.0f / %d |" % (p["t"], p["r_a"], p["r_b"],
                                                           pm(p["distance"], p["error"], 3), p["noise_floor"],
                                                           p["chi2"], p["dof"]))
        print()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("root", help="data/paper-runs")
    a = ap.parse_args()
    for name, table in (("fig1", fig1), ("fig2", fig2), ("fig4", fig4)):
        d = os.path.join(a.root, name)
        if os.path.isdir(d):
            print("### %s\n" % name)
            table(d)
            print()


if __name__ == "__main__":
    main()
