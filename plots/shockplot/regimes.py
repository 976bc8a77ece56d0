"""regimes.png (a particle gas whose cooling shows all three regimes): T(t)
through the elastic, homogeneous-cooling and sticky regimes, shaded between
the theory's crossover times 1/eps and eps^(-3/2), with the homogeneous-cooling
law of eq. 2 (A = 1) from the measured T(0), the late fit, and the local
exponent d ln T / d ln t against the plateaus 0, -2 and -2/3 with the
measured crossovers."""
import matplotlib.pyplot as plt

from .common import GUIDE, attr, finish, fraction, is_gas, label, theory, unit
from .temperature import ALPHA_NAME, DATA, FIT, T_NAME, TIME_NAME, exponent_ticks, fit_label

BANDS = [("elastic", "#eeeeee"), ("homogeneous cooling", "#dde8f5"), ("sticky gas (clusters)", "#f5e6d6")]


def shows_regimes(f, summary):
    """A gas (common.is_gas) whose local exponent crossed into the sticky regime, where the
    crossovers' theory holds (its bands are drawn at its t_dissip and t_stick)."""
    return is_gas(summary) and summary.get("analysis", {}).get("t_stick") is not None and \
        theory(summary, "crossovers") is not None and "particles/analysis/T_local_exponent" in f


def _homogeneous_cooling(summary, t):
    """T(0) (1 + eps t)^-2, eps = (1 - r) / 2 (shockgas/compare/theory.hpp, eq. 2 with A = 1)."""
    r = summary.get("particles", {}).get("r")
    T0 = summary.get("initial", {}).get("temperature")
    if r is None or T0 is None or len(t) == 0:
        return None
    return T0 / (1 + (1 - r) / 2 * t) ** 2


def _bands(axes, t, t_dissip, t_stick):
    for (name, colour), (lo, hi) in zip(BANDS, [(t[0], t_dissip), (t_dissip, t_stick), (t_stick, t[-1])]):
        for ax in axes:
            named = {"label": f"theory: {name} regime"} if ax is axes[0] else {}
            ax.axvspan(lo, hi, color=colour, lw=0, zorder=0, **named)


def _temperature(ax, p, summary, t, T, t_stick):
    a = summary.get("analysis", {})
    ax.loglog(t, T, ls="none", **DATA, label="particles: T (top), its local exponent (bottom)")
    early = t <= 3 * t_stick
    haff = _homogeneous_cooling(summary, t[early])
    if haff is not None:
        ax.loglog(t[early], haff, "-.", color="0.3", lw=1.4, zorder=4,
                  label=r"theory: homogeneous cooling $T(0)\,(1 + \epsilon t)^{-2}$ (A = 1)")
    an = p["analysis"]
    if "T_fit_t" in an:
        window = an["T_fit_t"][:]
        ax.loglog(window, an["T_fit_T"][:], "-", **FIT,
                  label=fit_label(window, a.get("T_exponent", float("nan")), summary))
    ax.set_ylabel(label(T_NAME, unit(p["T"])))
    # Haff's law bends towards t^-2 between t_dissip and t_stick; it reaches it only where they lie
    # far apart (the local exponent below says how close this gas came).
    ax.set_title("the three regimes of a cooling gas: $T \\sim 1$, $T(0)(1 + \\epsilon t)^{-2}$ (towards $t^{-2}$), "
                 "$t^{-2/3}$", fontsize=10)


def _exponent(ax, p, summary, ok):
    a = summary.get("analysis", {})
    an = p["analysis"]
    ax.semilogx(p["t"][:][ok], p["analysis/T_local_exponent"][:][ok], "-", **DATA)
    levels = [0.0, attr(an, "T_cooling_exponent_theory", -2.0), attr(an, "T_exponent_theory", -2 / 3)]
    for k, level in enumerate(levels):
        ax.axhline(level, ls="--", **GUIDE, label="theory: exponent " + ", ".join(fraction(v) for v in levels)
                   if k == 0 else None)
    exponent_ticks(ax, levels)
    for key, colour in [("t_dissip", "tab:green"), ("t_stick", "tab:purple")]:
        if a.get(key) is None:
            continue
        predicted = a.get(key + "_theory")  # null where the crossovers' theory does not hold
        ax.axvline(a[key], color=colour, lw=1.2,
                   label=f"measured {key} = {a[key]:.3g} " +
                   (f"(theory {predicted:.3g})" if predicted is not None else "(no theory for this scene)"))
    ax.set_ylim(-2.4, 0.4)
    ax.set_xlabel(label(TIME_NAME, unit(p["t"])))
    ax.set_ylabel(label(ALPHA_NAME, "1"))


def figure_regimes(f, summary):
    if not shows_regimes(f, summary):
        return None
    a = summary["analysis"]
    p = f["particles"]
    t, T = p["t"][:], p["T"][:]
    ok = (t > 0) & (T > 0)
    t, T = t[ok], T[ok]
    fig, (ax_T, ax_a) = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    _bands((ax_T, ax_a), t, a["t_dissip_theory"], a["t_stick_theory"])
    _temperature(ax_T, p, summary, t, T, a["t_stick_theory"])
    _exponent(ax_a, p, summary, ok)
    finish(fig, (ax_T, ax_a), columns=1)
    return fig
