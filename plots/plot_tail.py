#!/usr/bin/python3
"""Charts of `shockgas tail` (docs/paper.md, the tail of Phi(z)).

    plots/plot_tail.py DIR [DIR ...] --out docs/img/paper

Each DIR holds tail_phi.csv, tail_windows.csv and tail_runs.csv of one study
(one restitution, one or more sizes N). Draws, for the largest N of each r:

  tail-phi-rR.png    ln(-ln Phi) against ln|z| at every time, with the exact
                     mass-weighted law's bin means and a slope-3 guide;
  tail-local-rR.png  the local exponent d ln(-ln Phi)/d ln|z| of the data
                     (jackknife errors) beside the exact law's at the same z;
and over all DIRs and sizes:
  tail-windows.png   the slope of ln(-ln Phi) on |z| in [1, 2] against t, per
                     r and N, with the exact law's on the same bins.
Reads only the CSV files.
"""
import argparse
import math
import os
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from shockplot.run_files import read_csv  # noqa: E402
from shockplot.saving import save  # noqa: E402

PHI, WINDOWS = "tail_phi.csv", "tail_windows.csv"


def read(path):
    """A table of the tail study, every cell a float (nan where empty)."""
    return read_csv(path, numbers=True)


def write(fig, out, name, source):
    fig.tight_layout()
    save(fig, os.path.join(out, name), source, dpi=120, tight=False)


def by(rows, *keys):
    out = defaultdict(list)
    for r in rows:
        out[tuple(r[k] for k in keys)].append(r)
    return out


def tag(r):
    return ("%g" % r).replace(".", "")


def plot_phi(phi, r, N, out):
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    times = sorted({p["t"] for p in phi})
    colours = plt.cm.viridis([i / max(1, len(times) - 1) for i in range(len(times))])
    for t, c in zip(times, colours):
        pts = [p for p in phi if p["t"] == t and p["z"] >= 0.5 and 0 < p["phi"] < 1]
        x = [math.log(p["z"]) for p in pts]
        y = [math.log(-math.log(p["phi"])) for p in pts]
        # error of ln(-ln phi) from that of phi: |d/dphi| = 1 / (phi |ln phi|)
        e = [p["phi_error"] / (p["phi"] * abs(math.log(p["phi"]))) for p in pts]
        ax.errorbar(x, y, yerr=e, fmt="o", ms=2.5, color=c, elinewidth=0.8, label="t = %g" % t)
    law = [p for p in phi if p["t"] == times[-1] and p["z"] >= 0.5 and 0 < p["exact_phi"] < 1]
    zmax = max(p["z"] for p in phi)
    exact = sorted({(p["z"], p["exact_phi"]) for p in phi if p["z"] >= 0.5 and 0 < p["exact_phi"] < 1})
    ax.plot([math.log(z) for z, _ in exact], [math.log(-math.log(f)) for _, f in exact], "k--", lw=1.2,
            label="exact mass-weighted law (bin means)")
    if law:
        x0, y0 = math.log(exact[-1][0]), math.log(-math.log(exact[-1][1]))
        xs = [math.log(0.8), math.log(zmax)]
        ax.plot(xs, [y0 + 3 * (x - x0) for x in xs], "k:", lw=1, label="slope 3 (exp(-c|z|^3))")
    ax.set_xlabel("ln |z|,  z = (v - <v>) t^(1/3)")
    ax.set_ylabel("ln(-ln Phi(z))")
    ax.set_title("r = %g: N = %.0e per realization, mass weighted, folded" % (r, N))
    ax.legend(fontsize=8)
    write(fig, out, "tail-phi-r%s.png" % tag(r), PHI)


def plot_local(phi, r, N, out):
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    times = sorted({p["t"] for p in phi})
    colours = plt.cm.viridis([i / max(1, len(times) - 1) for i in range(len(times))])
    for k, (t, c) in enumerate(zip(times, colours)):
        pts = [p for p in phi if p["t"] == t and not math.isnan(p["local_exponent"])]
        dz = 0.008 * (k - len(times) / 2)  # side by side
        ax.errorbar([p["z"] + dz for p in pts], [p["local_exponent"] for p in pts],
                    yerr=[p["local_exponent_error"] for p in pts], fmt="o", ms=2.5, color=c,
                    elinewidth=0.8, label="t = %g" % t)
    law = sorted({(p["z"], p["exact_local"]) for p in phi if not math.isnan(p["exact_local"])})
    bins = sorted({(p["z"], p["exact_local_bins"]) for p in phi if not math.isnan(p["exact_local_bins"])})
    ax.plot([z for z, _ in law], [a for _, a in law], "k--", lw=1.2, label="exact law, d ln(-ln Phi)/d ln|z|")
    ax.plot([z for z, _ in bins], [a for _, a in bins], "k-.", lw=0.8, label="exact law, same estimator on bins")
    ax.axhline(3, color="grey", ls=":", lw=1, label="3 (the asymptotic exponent)")
    ax.set_ylim(1.3, 3.1)
    ax.set_xlabel("|z|")
    ax.set_ylabel("local exponent a(z)")
    ax.set_title("r = %g: N = %.0e per realization; bins with >= 25 clusters" % (r, N))
    ax.legend(fontsize=8, loc="upper left")
    write(fig, out, "tail-local-r%s.png" % tag(r), PHI)


def plot_windows(studies, out):
    # The straight-line slope of ln(-ln Phi) on ln|z| over |z| in [1, 2] (every
    # study reaches 2 at t >= 10^3): steadier than the three-parameter fit of a.
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    markers = "os^Dv<>"
    k = 0
    exact = None
    for r, windows in studies:
        for (N,), rows in sorted(by(windows, "N").items()):
            pts = [w for w in rows if w["z_lo"] == 1.0 and abs(w["z_hi"] - 2.0) < 1e-9]
            if not pts:
                continue
            exact = pts[0]["exact_slope"]
            ax.errorbar([w["t"] * (1 + 0.05 * k) for w in pts], [w["slope"] for w in pts],
                        yerr=[w["slope_error"] for w in pts], fmt=markers[k % len(markers)] + "-", ms=4, lw=0.8,
                        capsize=2, label="r = %g, N = %.0e" % (r, N))
            k += 1
    if exact is not None:
        ax.axhline(exact, color="k", lw=1, ls="--", label="exact mass-weighted law, same bins: %.3f" % exact)
    ax.set_xscale("log")
    ax.set_xlabel("t")
    ax.set_ylabel("slope of ln(-ln Phi) on ln|z|, |z| in [1, 2]")
    ax.set_title("tail exponent on [1, 2] (jackknife errors); exp(-c|z|^3) would give 3")
    ax.legend(fontsize=7)
    write(fig, out, "tail-windows.png", WINDOWS)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dirs", nargs="+")
    ap.add_argument("--out", default=".")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    studies, largest = [], {}  # largest: r -> (N, its rows of tail_phi.csv)
    for d in a.dirs:
        phi = read(os.path.join(d, PHI))
        r, N = phi[0]["r"], max(p["N"] for p in phi)
        if N > largest.get(r, (0, None))[0]:
            largest[r] = (N, [p for p in phi if p["N"] == N])
        studies.append((r, read(os.path.join(d, WINDOWS))))
    for r, (N, rows) in largest.items():
        plot_phi(rows, r, N, a.out)
        plot_local(rows, r, N, a.out)
    plot_windows(studies, a.out)


if __name__ == "__main__":
    main()
