#!/usr/bin/python3
"""Plots of a shockgas result directory, read only from its result files.

Usage: /usr/bin/python3 scripts/plot_result.py DIR
Writes DIR/*.png. Exit code 3 when matplotlib or h5py is missing.
"""
import os
import sys
from fractions import Fraction

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from plot_evolution import plot_evolution, plot_regimes
except ImportError as exc:  # the command turns this into a warning
    print(f"plot_result.py: {exc}", file=sys.stderr)
    sys.exit(3)


def attr(obj, name, default=None):
    value = obj.attrs.get(name, default)
    return value.decode() if isinstance(value, bytes) else value


def save(fig, out_dir, name):
    fig.tight_layout()
    # the first axes' title names the picture in report.html (PNG tEXt "Title")
    title = next((ax.get_title() for ax in fig.axes if ax.get_title()), "")
    fig.savefig(os.path.join(out_dir, name), dpi=110, metadata={"Title": title} if title else None)
    plt.close(fig)


def plot_temperature(f, out_dir):
    p = f["particles"]
    t, T = p["t"][:], p["T"][:]
    ok = (t > 0) & (T > 0)
    if ok.sum() < 2:
        return
    t, T = t[ok], T[ok]
    err = p["T_stderr"][:][ok] if "T_stderr" in p else None
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.errorbar(t, T, yerr=err, fmt="o-", ms=3, label="particles")
    if "analysis" in p and "T_fit_t" in p["analysis"]:
        a = p["analysis"]
        ax.plot(a["T_fit_t"][:], a["T_fit_T"][:], "k-", lw=2, alpha=0.6,
                label=f"fit: T ~ t^{attr(a, 'T_exponent', 0):.3f}")
    # guides, with the exponents the result file states (compare/theory.hpp): the
    # homogeneous-cooling law through the steepest point, the sticky-gas law
    # through the last point, each over two decades
    slopes = np.gradient(np.log(T), np.log(t))
    steep = int(np.argmin(slopes))
    a = p["analysis"] if "analysis" in p else None
    guides = [] if a is None else [(attr(a, "T_cooling_exponent_theory"), steep, "--"),
                                   (attr(a, "T_exponent_theory"), len(t) - 1, ":")]
    for power, anchor, style in [g for g in guides if g[0] is not None]:
        label = f"t^{Fraction(power).limit_denominator(12)}"
        tt = t[(t >= t[anchor] / 10) & (t <= t[anchor] * 10)]
        ax.plot(tt, T[anchor] * (tt / t[anchor]) ** power, style, color="gray", label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(T.min() / 3, T.max() * 3)
    ax.set_xlabel("t")
    ax.set_ylabel("T(t)")
    ax.set_title("temperature")
    ax.legend()
    save(fig, out_dir, "temperature.png")


def plot_histogram(f, out_dir):
    h = f["particles/histogram"]
    z, t, density = h["z"][:], h["t"][:], h["density"][:]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    rows = np.unique(np.linspace(len(t) // 2, len(t) - 1, 4).astype(int))
    for k in rows:
        ax.semilogy(z, np.where(density[k] > 0, density[k], np.nan), "o-", ms=2, label=f"t = {t[k]:.3g}")
    ax.set_xlabel("z = v t^(1/3)")
    ax.set_ylabel("Phi(z)")
    ax.set_title("scaled velocity distribution")
    ax.legend()
    save(fig, out_dir, "velocity_distribution.png")


def plot_spacetime(f, out_dir):
    s = f["particles/spacetime"]
    t, x = s["t"][:], s["x"][:]
    fig, ax = plt.subplots(figsize=(6, 6))
    step = max(1, x.shape[1] // 400)
    for j in range(0, x.shape[1], step):
        xs = x[:, j].copy()
        jumps = np.abs(np.diff(xs)) > 0.5 * (np.nanmax(x) - np.nanmin(x))
        xs[1:][jumps] = np.nan  # do not draw wrap-around lines on the ring
        ax.plot(xs, t, "k-", lw=0.3)
    ax.set_xlabel("x")
    ax.set_ylabel("t")
    ax.set_title("space-time diagram")
    save(fig, out_dir, "spacetime.png")


def plot_fields(f, out_dir):
    """Every solver's v and rho, each in the label and colour its registration gives
    (attributes `label`, `colour` of /continuum/<solver>), over the particles."""
    c = f["continuum"]
    fig, (av, ar) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for name in c:
        g = c[name]
        if "x" not in g:
            continue
        style = {"lw": 1, "label": attr(g, "label", name), "color": attr(g, "colour")}
        av.plot(g["x"][:], g["v"][:], **style)
        if "rho" in g and g["rho"].shape == g["x"].shape:
            ar.plot(g["x"][:], g["rho"][:], **style)
    if "compare" in f and "x" in f["compare"]:
        cmp = f["compare"]
        av.plot(cmp["x"][:], cmp["v_particles"][:], "k.", ms=2, label="particles")
        ar.plot(cmp["x"][:], cmp["rho_particles"][:], "k.", ms=2, label="particles")
        # the clusters and shocks counted by the comparison (mass >= min_mass)
        min_mass = attr(cmp, "min_mass", 0.0)
        for name, mass, marker, color in [("clusters", "clusters_m", "v", "tab:red"),
                                          ("shocks", "shocks_mass", "^", "tab:blue")]:
            if name + "_x" in cmp:
                xs = cmp[name + "_x"][:][cmp[mass][:] >= min_mass]
                ar.plot(xs, np.zeros_like(xs), marker, color=color, ms=7, label=f"{name} (mass >= {min_mass:.3g})")
    ar.set_yscale("symlog", linthresh=1.0)
    av.set_ylabel("v")
    ar.set_ylabel("rho")
    ar.set_xlabel("x")
    av.set_title(f"fields at t = {attr(next(iter(c.values())), 't', 0):.4g}")
    av.legend(fontsize=7)
    if ar.get_legend_handles_labels()[0]:
        ar.legend(fontsize=7)
    save(fig, out_dir, "fields.png")


def plot_sweep(f, out_dir):
    """Every variant of a [sweep] scene in one T(t) plot and one Phi(z) plot."""
    groups = sorted(f["sweep"], key=int)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    last = None
    for k in groups:
        g = f["sweep"][k]
        if "particles/T" not in g:
            continue
        t, T = g["particles/t"][:], g["particles/T"][:]
        ok = (t > 0) & (T > 0)
        ax.loglog(t[ok], T[ok], "o-", ms=3, label=attr(g, "label", k))
        last = (t[ok], T[ok])
    if last is not None:
        t, T = last
        power = attr(f["sweep"], "T_exponent_theory")
        if power is not None:
            ax.loglog(t, T[-1] * (t / t[-1]) ** power, ":", color="gray",
                      label=f"t^{Fraction(power).limit_denominator(12)}")
        unit = {name: attr(g["particles/" + name], "unit", "") for name in ("t", "T")}
        ax.set_xlabel(f"time t [{unit['t']}]")
        ax.set_ylabel(f"temperature T [{unit['T']}]")
        ax.set_title("temperature of each variant")
        ax.legend(fontsize=8)
        save(fig, out_dir, "temperature.png")
    else:
        plt.close(fig)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    drawn = False
    for k in groups:
        g = f["sweep"][k]
        if "particles/histogram" not in g:
            continue
        h = g["particles/histogram"]
        z, t, density = h["z"][:], h["t"][:], h["density"][:]
        for row in range(len(t)):
            if t[row] >= 100 and row >= len(t) - 3:
                ax.semilogy(z, np.where(density[row] > 0, density[row], np.nan), ".-", ms=3,
                            label=f"{attr(g, 'label', k)}, t = {t[row]:.3g}")
                drawn = True
    if drawn:
        ax.set_xlabel("z = v t^(1/3)")
        ax.set_ylabel("Phi(z)")
        ax.legend(fontsize=6)
        save(fig, out_dir, "velocity_distribution.png")
    else:
        plt.close(fig)


def main():
    out_dir = sys.argv[1]
    with h5py.File(os.path.join(out_dir, "result.h5"), "r") as f:
        if "sweep" in f:
            plot_sweep(f, out_dir)
        if "particles" in f and "T" in f["particles"]:
            plot_temperature(f, out_dir)
        if "particles/histogram" in f:
            plot_histogram(f, out_dir)
        if "particles/spacetime" in f:
            plot_spacetime(f, out_dir)
        if "continuum" in f:
            plot_fields(f, out_dir)
        if "animation/evolution" in f:
            plot_evolution(f, out_dir)
        if "particles/analysis" in f:
            plot_regimes(f, out_dir)


if __name__ == "__main__":
    main()
