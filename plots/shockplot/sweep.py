"""A [sweep] scene's own plots: every variant's T(t) with its local exponent,
and every variant's Phi(z) at its late times, over the exact laws of a
white-noise start where the result file holds them."""
import matplotlib.pyplot as plt
import numpy as np

from .common import (EXACT, GUIDE, attr, draw_guide, finish, fraction, label, note_no_theory, power_law,
                     sticky_regime_start, theory, unit)
from .distribution import axes_labels, draw_exact
from .temperature import ALPHA_NAME, T_NAME, TIME_NAME, exponent_ticks


def _variants(f, needs):
    groups = sorted(f["sweep"], key=int)
    return [(k, f["sweep"][k]) for k in groups if needs in f["sweep"][k]]


def _local_exponent(t, T):
    """d ln T / d ln t by centred differences (one-sided at the ends)."""
    return np.gradient(np.log(T), np.log(t))


def earliest_sticky_start(summary):
    """The earliest start of the sticky regime (10 t_stick) over the variants (their own summaries), if
    any variant reaches it."""
    times = [sticky_regime_start(v.get("summary", {})) for v in summary.get("variants", [])]
    times = [t for t in times if t is not None]
    return min(times) if times else None


def figure_sweep_temperature(f, summary):
    variants = _variants(f, "particles/T")
    if not variants:
        return None
    fig, (ax_T, ax_a) = plt.subplots(2, 1, figsize=(8, 8), sharex=True, gridspec_kw={"height_ratios": [3, 2]})
    colours = plt.cm.tab10(np.arange(len(variants)) % 10)
    exact, last = None, None
    for (k, g), colour in zip(variants, colours):
        t, T = g["particles/t"][:], g["particles/T"][:]
        ok = (t > 0) & (T > 0)
        name = attr(g, "label", k)
        ax_T.errorbar(t[ok], T[ok], yerr=g["particles/T_stderr"][:][ok] if "particles/T_stderr" in g else None,
                      color=colour, marker="o", ms=3, lw=1, label=name)
        ax_a.plot(t[ok], _local_exponent(t[ok], T[ok]), color=colour, marker="o", ms=2.5, lw=1, label=name)
        exact = exact or attr(g["particles"], "T_amplitude_exact")
        last = (t[ok], T[ok], g)
    power = attr(f["sweep"], "T_exponent_theory", -2 / 3)
    t, T, g = last
    start = earliest_sticky_start(summary)
    # The sticky-gas law where it holds for a variant (theory.sticky_cooling of its summary), else the words.
    if not any(theory(v.get("summary", {}), "sticky_cooling") for v in summary.get("variants", [])):
        note_no_theory(ax_a, summary.get("variants", [{}])[-1].get("summary", {}), "sticky_cooling")
    elif exact is not None and (start is None or start < t[-1]):
        tt = np.geomspace(max(t[0], start or t[0]), t[-1], 50)
        ax_T.plot(tt, exact * tt ** power, **EXACT,
                  label=f"exact: late-time law of the sticky gas from this white noise, {power_law(exact, power)}")
    else:
        draw_guide(ax_T, t, T, power, (t[-1] / 10, t[-1]), (t[0], t[-1]), "sticky gas")
    if any(theory(v.get("summary", {}), "sticky_cooling") for v in summary.get("variants", [])):
        ax_a.axhline(power, ls="--", **GUIDE, label=f"theory: exponent {fraction(power)} (sticky gas)")
    exponent_ticks(ax_a, [power])
    ax_T.set_xscale("log")
    ax_T.set_yscale("log")
    ax_T.set_ylabel(label(T_NAME, unit(g["particles/T"])))
    ax_a.set_ylabel(label(ALPHA_NAME, "1"))
    ax_a.set_xlabel(label(TIME_NAME, unit(g["particles/t"])))
    ax_a.set_ylim(-2.6, 0.4)
    ax_T.set_title("temperature of each variant (top), its local exponent by centred differences (bottom)",
                   fontsize=10)
    finish(fig, (ax_T, ax_a), columns=2)
    return fig


def figure_sweep_distribution(f):
    variants = _variants(f, "particles/histogram")
    if not variants:
        return None
    fig, ax = plt.subplots(figsize=(8, 6))
    colours = plt.cm.tab10(np.arange(len(variants)) % 10)
    styles = ["-", "--", ":"]
    exact, h, rows = None, None, []
    for (k, g), colour in zip(variants, colours):
        h = g["particles/histogram"]
        z, t, density = h["z"][:], h["t"][:], h["density"][:]
        late = [row for row in range(len(t)) if row >= len(t) - 3]
        for s, row in enumerate(late):
            rows.append(density[row])
            ax.plot(z, np.where(density[row] > 0, density[row], np.nan), styles[s % 3], marker=".", ms=3,
                    lw=0.9, color=colour, label=f"{attr(g, 'label', k)}, t = {t[row]:.3g}")
        if exact is None and "exact" in h:
            exact = (z, h["exact"][:])
    if exact is not None:
        draw_exact(ax, *exact)
    axes_labels(ax, h, rows)
    ax.set_title(r"scaled velocity distribution $\Phi(z)$ of each variant at its last three samples", fontsize=10)
    finish(fig, [ax], columns=3, fontsize=7)
    return fig
