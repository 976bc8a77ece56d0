#!/usr/bin/env python3
"""Charts of `shockgas bench` (docs/performance.md), drawn from the CSV files only.

Usage: plot_bench.py DIR   -- writes DIR/<name>.png next to each DIR/<name>.csv,
each whole or not at all. Exit code 3 if matplotlib is missing (the command turns
that into a warning); 4, with one line "cannot write PATH: REASON" on stderr, when
a chart cannot be written (a full disk).
"""
import math
import os
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from shockplot.run_files import read_csv
    from shockplot.saving import CannotWrite, save
except ImportError as exc:
    print(f"plot_bench.py: {exc}", file=sys.stderr)
    sys.exit(3)


def read(directory, name):
    """The rows of DIR/name (text cells); none when the study did not run."""
    return read_csv(os.path.join(directory, name), missing=[])


def num(row, key):
    """The number in a cell; None for an empty cell (not applicable)."""
    value = row.get(key, "")
    return float(value) if value not in ("", None) else None


def positive(xs, ys, keep_order=False):
    pts = [(x, y) for x, y in zip(xs, ys) if x and y and x > 0 and y > 0]
    pts = pts if keep_order else sorted(pts)
    return [p[0] for p in pts], [p[1] for p in pts]


def chart(fig, directory, name, table):
    """DIR/name.png drawn from DIR/table, whole or not at all (saving.save);
    CannotWrite when the system refuses it."""
    fig.tight_layout()
    save(fig, os.path.join(directory, name + ".png"), table, dpi=90, tight=False)


def grouped(rows, key):
    groups = {}
    for r in rows:
        groups.setdefault(r[key], []).append(r)
    return groups


def work_precision(directory, name, error, title):
    rows = read(directory, name + ".csv")
    if not rows:
        return
    problems = list(grouped(rows, "problem"))
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5))
    for ax, problem in zip(axes.flat, problems):
        exact = []
        for method, rs in grouped([r for r in rows if r["problem"] == problem], "method").items():
            x, y = positive([num(r, "seconds") for r in rs], [num(r, error) for r in rs], keep_order=True)
            if x:
                label = method + (" (one point per nu)" if method.startswith("hopf_cole") and name == "wp_inviscid" else "")
                ax.loglog(x, y, "o-", ms=3, label=label)
            elif all(num(r, error) == 0 for r in rs):
                exact += [(method, num(r, "seconds")) for r in rs]
        if exact and ax.lines:
            bottom = ax.get_ylim()[0]
            ax.loglog([t for _, t in exact], [bottom * 1.3] * len(exact), "kv", ms=5,
                      label=exact[0][0] + ": time only (error 0)")
        ax.set_title(f"{problem}: {title}")
        ax.set_xlabel("wall time, median of runs [s]")
        ax.set_ylabel(error)
        ax.grid(True, which="both", alpha=0.3)
        if ax.lines:
            ax.legend(fontsize=6)
    chart(fig, directory, name + ("" if error == "l1" else "_" + error), name + ".csv")


def particles_cost(directory):
    rows = read(directory, "particles_cost.csv")
    if not rows:
        return
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, (scan, key, label) in zip(axes, [("N", "N", "N particles (t_end = 100)"),
                                             ("collisions", "collisions_per_particle", "collisions per particle")]):
        rs = [r for r in rows if r["scan"] == scan]
        x, y = positive([num(r, key) for r in rs], [num(r, "seconds") for r in rs])
        ax.loglog(x, y, "o-", label="events engine")
        for r in rs:
            if num(r, "ns_per_collision"):
                ax.annotate(f"{num(r, 'ns_per_collision'):.0f} ns", (num(r, key), num(r, "seconds")), fontsize=6)
        ax.set_xlabel(label)
        ax.set_ylabel("wall time [s]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    chart(fig, directory, "particles_cost", "particles_cost.csv")


def particles_statistics(directory):
    rows = read(directory, "particles_statistics.csv")
    if not rows:
        return
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for key, label in [("T_end_rel_error", "relative error of T(t_end)"), ("exponent_error", "error of the exponent")]:
        x, y = positive([num(r, "cpu_seconds") for r in rows], [num(r, key) for r in rows])
        ax.loglog(x, y, "o-", label=label)
    x, y = positive([num(r, "cpu_seconds") for r in rows], [num(r, "exponent_error") for r in rows])
    if x:
        ax.loglog(x, [y[0] * math.sqrt(x[0] / xi) for xi in x], "k:", label="~ cpu^-1/2")
    ax.set_xlabel("CPU time, sum over realizations [s]")
    ax.set_ylabel("statistical error")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    chart(fig, directory, "particles_statistics", "particles_statistics.csv")


def stability_cfl(directory):
    rows = read(directory, "stability_cfl.csv")
    if not rows:
        return
    problems = list(grouped(rows, "problem"))
    fig, axes = plt.subplots(1, len(problems), figsize=(5.5 * len(problems), 4.3), squeeze=False)
    floor, top = 1e-17, 10.0  # a step that never raised TV is drawn at the floor; a blow-up at the top
    for ax, problem in zip(axes.flat, problems):
        for method, rs in grouped([r for r in rows if r["problem"] == problem], "method").items():
            def value(r):
                if r["what"].startswith("blew up"):
                    return top
                return max(num(r, "max_tv_rise") or 0.0, floor)
            pts = [(num(r, "cfl"), value(r)) for r in rs]
            line, = ax.semilogy([p[0] for p in pts], [p[1] for p in pts], "o-", ms=3, label=method)
            bad = [p for p, r in zip(pts, rs) if r["failed"] == "yes"]
            ax.semilogy([p[0] for p in bad], [p[1] for p in bad], "x", color=line.get_color(), ms=8)
        ax.axvline(1.0, color="k", ls=":", label="predicted limit 1")
        ax.axhline(1e-8, color="r", ls=":", label="detection: rise > 1e-8 TV0")
        ax.set_title(f"{problem}: largest TV rise in one step (x = failed; 10 = blew up)", fontsize=9)
        ax.set_xlabel("Courant number")
        ax.set_ylabel("max_n (TV_n+1 - TV_n) / TV_0")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    chart(fig, directory, "stability_cfl", "stability_cfl.csv")


def stability_viscous(directory):
    rows = read(directory, "stability_viscous.csv")
    if not rows:
        return
    nus = sorted({num(r, "nu") for r in rows})
    fig, axes = plt.subplots(1, len(nus), figsize=(5 * len(nus), 4.3), squeeze=False)
    for ax, nu in zip(axes.flat, nus):
        ex = [r for r in rows if num(r, "nu") == nu and r["method"] == "explicit"]
        for failed, marker, label in [("no", "o", "explicit: stable"), ("yes", "x", "explicit: failed")]:
            rs = [r for r in ex if r["failed"] == failed]
            ax.loglog([num(r, "cells") for r in rs], [num(r, "c") for r in rs], marker, ms=5, label=label)
        cells = sorted({num(r, "cells") for r in ex})
        pred = [min(num(r, "c_predicted") for r in ex if num(r, "cells") == c) for c in cells]
        ax.loglog(cells, pred, "k-", label="predicted 1/(1 + |v| h/2nu)")
        ax.axhline(1.0, color="k", ls=":", label="dt = h^2/2nu")
        for method, marker in [("cvode", "s"), ("arkode", "^")]:
            rs = [r for r in rows if num(r, "nu") == nu and r["method"] == method and num(r, "c")]
            ax.loglog([num(r, "cells") for r in rs], [num(r, "c") for r in rs], marker, ms=6,
                      label=f"{method}: mean step")
        ax.set_title(f"nu = {nu:g}")
        ax.set_xlabel("cells (h = 1/cells)")
        ax.set_ylabel("dt / (h^2 / 2 nu)")
        ax.grid(True, which="both", alpha=0.3)
        if ax.lines:
            ax.legend(fontsize=6)
    chart(fig, directory, "stability_viscous", "stability_viscous.csv")


def stability_hopf_cole(directory):
    rows = read(directory, "stability_hopf_cole.csv")
    if not rows:
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    x, y = positive([num(r, "ratio") for r in rows], [num(r, "fft_error") for r in rows])
    ax.loglog(x, y, "o-", label="FFT path: max |v_fft - v_log|")
    x, y = positive([num(r, "ratio") for r in rows], [num(r, "fft_bound") for r in rows])
    ax.loglog(x, y, "--", label="FFT path's own bound")
    bad = [num(r, "ratio") for r in rows if r["fft_finite"] == "no"]
    if bad:
        ax.loglog(bad, [1e2] * len(bad), "rx", ms=8, label="non-finite")
    ax.axhline(1.5e-3, color="k", ls=":", label="1e-3 max|v0| (digits lost)")
    ax.axvline(709, color="r", ls=":", label="exp range, 709")
    ax.set_ylim(1e-16, 1e3)
    ax.set_xlabel("DeltaPsi / 2 nu")
    ax.set_ylabel("velocity error [length/time]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    chart(fig, directory, "stability_hopf_cole", "stability_hopf_cole.csv")


def stability_collapse(directory):
    rows = read(directory, "stability_collapse.csv")
    if not rows:
        return
    ring = [r for r in rows if r["geometry"] == "ring"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.3))
    for r_value, rs in grouped(ring, "r").items():
        line, = axes[0].semilogx([num(r, "N") for r in rs], [num(r, "collapsed_fraction") for r in rs], "o-",
                                 label=f"r = {r_value}")
        axes[0].axvline(num(rs[0], "N_c_predicted"), color=line.get_color(), ls=":")
        x, y = positive([num(r, "N") for r in rs], [num(r, "median_collapse_time") for r in rs])
        axes[1].loglog(x, y, "o-", color=line.get_color(), label=f"r = {r_value}")
    axes[0].set_xlabel("N (ring, delta = 0); dotted: McNamara-Young -ln(1-r)/(1-r)")
    axes[0].set_ylabel("fraction of realizations collapsed")
    axes[1].set_xlabel("N")
    axes[1].set_ylabel("median collapse time [time]")
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    chart(fig, directory, "stability_collapse", "stability_collapse.csv")


def stability_threshold(directory):
    rows = read(directory, "stability_threshold.csv")
    if not rows:
        return
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for r_value, rs in grouped(rows, "r").items():
        x, y = positive([num(r, "delta") for r in rs], [num(r, "t_departs") for r in rs])
        ax.loglog(x, y, "o-", label=f"r = {r_value}: T departs by 20 %")
    ds = sorted({num(r, "delta") for r in rows})
    ax.loglog(ds, [d ** -3 for d in ds], "k:", label="t_valid = delta^-3")
    ax.set_xlabel("threshold delta [length/time]")
    ax.set_ylabel("time [time]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    chart(fig, directory, "stability_threshold", "stability_threshold.csv")


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    d = sys.argv[1]
    work_precision(d, "wp_inviscid", "l1", "L1 error vs exact Hopf-Lax")
    work_precision(d, "wp_inviscid", "linf", "Linf error vs exact Hopf-Lax")
    work_precision(d, "wp_inviscid", "shock_error", "shock position error")
    work_precision(d, "wp_viscous", "l1", "L1 error vs exact Hopf-Cole, same nu")
    particles_cost(d)
    particles_statistics(d)
    stability_cfl(d)
    stability_viscous(d)
    stability_hopf_cole(d)
    stability_collapse(d)
    stability_threshold(d)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except CannotWrite as exc:  # the command ends with this line
        print(f"plot_bench.py: {exc}", file=sys.stderr)
        sys.exit(4)
