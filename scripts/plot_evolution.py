"""Teaching plots of a shockgas result, read only from its result files
(result.h5 and summary.json); called by scripts/plot_result.py.

evolution.png (a run with [output] animation = true and continuum solvers): how
the measured solver's wave evolves over the frames -- the breaking line
-1/min dv/dx = t* - t before the first shock, the amplitude's decay with its
fit, the lobes' areas, the number of shocks.

regimes.png (a particle run whose cooling shows all three regimes): T(t) with
the elastic, homogeneous-cooling and sticky regimes, and the local exponent
d ln T / d ln t against the plateaus 0, -2 and -2/3.
"""
import json
import os
from fractions import Fraction

import matplotlib.pyplot as plt
import numpy as np


def _unit(ds):
    u = ds.attrs.get("unit", "")
    return u.decode() if isinstance(u, bytes) else u


def _label(name, u):
    return f"{name} [{u}]" if u and u != "1" else name


def read_summary(out_dir):
    path = os.path.join(out_dir, "summary.json")
    return json.load(open(path)) if os.path.exists(path) else {}


def _breaking(ax, e, t, s, t_unit):
    """-1 / min dv/dx against t over the smooth frames, and the theory line t* - t."""
    shocks = e["shocks"][:]
    smooth = np.cumsum(shocks * (t > 0)) == 0
    slope = e["steepest_slope"][:]
    ok = smooth & (slope < 0)
    if ok.sum() < 2:
        ax.set_visible(False)
        return
    fitted = ok & (e["breaking_fit"][:] > 0)
    ax.plot(t[fitted], -1 / slope[fitted], "o", ms=5, color="tab:blue", label="measured: -1 / min dv/dx (fitted)")
    rest = ok & ~fitted
    if rest.any():
        ax.plot(t[rest], -1 / slope[rest], "o", ms=5, mfc="none", color="tab:blue",
                label="slope too steep for the grid (not fitted)")
    theory = s.get("breaking_time_theory")
    if theory is not None:
        tt = np.linspace(0, theory, 50)
        ax.plot(tt, theory - tt, "k--", lw=1.4, label=f"exact: t* - t, t* = 1/max(-v0') = {theory:.4g}")
    measured = s.get("shock_formation_time")
    if measured is not None:
        ax.axvline(measured, color="tab:red", lw=1, label=f"measured t* = {measured:.4g}")
    ax.set_xlim(0, max(t[ok].max(), theory or 0) * 1.05)
    ax.set_ylim(0, None)
    ax.set_xlabel(_label("time t", t_unit))
    ax.set_ylabel(_label("-1 / min dv/dx", t_unit))
    ax.set_title("wave breaking: the steepest slope blows up at t*")
    ax.legend(fontsize=8)


def _time_axis(ax, t, log, t_unit):
    if log:
        ax.set_xscale("log")
    ax.set_xlabel(_label("time t", t_unit))


def _amplitude(ax, e, t, s, t_unit):
    a = e["amplitude"][:]
    ok = (t > 0) & (a > 0)
    ax.loglog(t[ok], a[ok], "o-", ms=3, color="tab:blue", label="measured: (max v - min v) / 2")
    if "amplitude_fit_t" in e:
        exponent = s.get("amplitude_exponent", float("nan"))
        ax.loglog(e["amplitude_fit_t"][:], e["amplitude_fit"][:], "-", color="tab:red", lw=2.5, alpha=0.7,
                  label=f"fit: t^{exponent:.3f}")
    ax.set_xlabel(_label("time t", t_unit))
    ax.set_ylabel(_label("amplitude", _unit(e["amplitude"])))
    ax.set_title("decay: N-wave t^(-1/2), periodic sawtooth t^-1")
    ax.legend(fontsize=8)


def _lobes(ax, e, t, t_unit, log):
    top = 1.1
    for name, colour, marker, label in [("positive_area", "tab:orange", "o", "lobes above the mean, A+(t) / A+(0)"),
                                        ("negative_area", "tab:purple", "x", "lobes below the mean, A-(t) / A-(0)")]:
        area = e[name][:]
        if area[0] != 0:
            keep = t > 0 if log else np.ones_like(t, dtype=bool)
            ax.plot(t[keep], area[keep] / area[0], marker + "-", ms=4, color=colour, label=label)
            top = max(top, 1.05 * np.max(area / area[0]))
    ax.set_ylim(0, top)
    _time_axis(ax, t, log, t_unit)
    ax.set_ylabel("area / initial area")
    ax.set_title("lobe areas (kept by an isolated wave)")
    ax.legend(fontsize=8)


def _shocks(ax, e, t, t_unit, log):
    keep = t > 0 if log else np.ones_like(t, dtype=bool)
    ax.step(t[keep], e["shocks"][:][keep], where="post", color="tab:blue", label="shocks")
    ax.set_ylim(0, None)
    _time_axis(ax, t, log, t_unit)
    ax.set_ylabel("shocks")
    ax.set_title("number of shocks")
    ax.yaxis.get_major_locator().set_params(integer=True)


def plot_evolution(f, out_dir):
    e = f["animation/evolution"]
    t = f["animation/t"][:]
    t_unit = _unit(f["animation/t"])
    s = read_summary(out_dir).get("evolution", {})
    solver = e.attrs.get("solver", "")
    solver = solver.decode() if isinstance(solver, bytes) else solver
    pos = t[t > 0]
    log = len(pos) > 2 and pos[-1] / pos[0] > 50  # log-spaced frames
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    _breaking(axes[0, 0], e, t, s, t_unit)
    _amplitude(axes[0, 1], e, t, s, t_unit)
    _lobes(axes[1, 0], e, t, t_unit, log)
    _shocks(axes[1, 1], e, t, t_unit, log)
    title = f"the wave in time ({solver}): breaking, decay, lobes, shocks"
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "evolution.png"), dpi=110, metadata={"Title": title})
    plt.close(fig)


def _homogeneous_cooling(summary, t):
    """The homogeneous-cooling law T(0) / (1 + A eps t)^2 with A = 1 (compare/theory.hpp)."""
    r = summary.get("particles", {}).get("r")
    T0 = summary.get("initial", {}).get("temperature")
    if r is None or T0 is None or len(t) == 0:
        return None
    eps = (1 - r) / 2
    return t, T0 / (1 + eps * t) ** 2


def plot_regimes(f, out_dir):
    """T(t) through its three regimes and the local exponent, when the run shows them."""
    summary = read_summary(out_dir)
    a = summary.get("analysis", {})
    gas = summary.get("initial", {}).get("N", 0) >= 100  # regimes of a gas, not of a few bodies
    if not gas or a.get("t_stick") is None or "particles/analysis/T_local_exponent" not in f:
        return
    p = f["particles"]
    t, T = p["t"][:], p["T"][:]
    alpha = p["analysis/T_local_exponent"][:]
    an = p["analysis"]
    theory = {"t_dissip": a["t_dissip_theory"], "t_stick": a["t_stick_theory"]}
    fig, (aT, aa) = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    bands = [(t[0], theory["t_dissip"], "elastic", "#eeeeee"),
             (theory["t_dissip"], theory["t_stick"], "homogeneous cooling", "#dde8f5"),
             (theory["t_stick"], t[-1], "sticky gas (clusters)", "#f5e6d6")]
    for ax in (aT, aa):
        for lo, hi, name, colour in bands:
            ax.axvspan(lo, hi, color=colour, lw=0, label=f"{name} (theory)" if ax is aT else None)
    aT.loglog(t, T, "o", ms=3, color="tab:blue", label="particles")
    haff = _homogeneous_cooling(read_summary(out_dir), t[t <= 3 * theory["t_stick"]])
    if haff is not None:
        aT.loglog(*haff, "-.", color="dimgray", lw=1.4, label="homogeneous cooling T(0) (1 + eps t)^-2 (A = 1)")
    if "T_fit_t" in an:
        aT.loglog(an["T_fit_t"][:], an["T_fit_T"][:], "-", color="tab:red", lw=2.5, alpha=0.8,
                  label=f"fit: t^{a.get('T_exponent', float('nan')):.3f}")
    aT.set_ylabel(_label("temperature T", _unit(p["T"])))
    aT.set_title("the three regimes of a cooling gas: T ~ 1, t^-2, t^(-2/3)")
    aT.legend(fontsize=8, loc="lower left")
    aa.semilogx(t, alpha, "o-", ms=3, color="tab:blue", label="d ln T / d ln t")
    for level in (0.0, an.attrs.get("T_cooling_exponent_theory", -2.0), an.attrs.get("T_exponent_theory", -2 / 3)):
        aa.axhline(level, color="k", ls="--", lw=1)
        aa.annotate(f"{Fraction(float(level)).limit_denominator(12)}", (t[0], level), xytext=(3, 3),
                    textcoords="offset points", fontsize=9)
    for key, colour in [("t_dissip", "tab:green"), ("t_stick", "tab:purple")]:
        aa.axvline(a[key], color=colour, lw=1.2, label=f"{key} measured {a[key]:.3g} (theory {theory[key]:.3g})")
    aa.set_ylim(-2.4, 0.4)
    aa.set_xlabel(_label("time t", _unit(p["t"])))
    aa.set_ylabel("local exponent")
    aa.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "regimes.png"), dpi=110,
                metadata={"Title": "the cooling law through its regimes, and its local exponent"})
    plt.close(fig)
