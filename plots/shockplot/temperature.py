"""temperature.png: T(t) of the particles with its fit, the exact late-time law
of a white-noise start (or a guide whose amplitude is fitted, never anchored on
one point), and the local exponent d ln T / d ln t against the theory's levels."""
import matplotlib.pyplot as plt
import numpy as np

from .common import (EXACT, GUIDE, attr, draw_guide, exponent_error_text, finish, fraction, label, no_theory_text,
                     power_law, sticky_regime_start, theory, unit)

FIT = {"color": "tab:red", "lw": 2.2, "alpha": 0.75, "zorder": 4}
DATA = {"color": "tab:blue", "marker": "o", "ms": 3, "lw": 1, "zorder": 3}
PARTICLES_LABEL = r"particles: $T$ $\pm$ standard error of the ensemble mean (top), its local exponent (bottom)"
T_NAME, ALPHA_NAME, TIME_NAME = "temperature $T$", r"local exponent $d\ln T/d\ln t$", "time $t$"


def regime_times(summary):
    """t_dissip = 1/eps and t_stick = eps^(-3/2) of the run (summary.json), if known."""
    a = summary.get("analysis", {})
    return a.get("t_dissip_theory"), a.get("t_stick_theory")


def fit_label(window, exponent, summary):
    """"fit on [a, b]: T ~ t^x, +- e (jackknife, n realizations)", or the words for no error."""
    a = summary.get("analysis", {})
    return (rf"fit on [{window[0]:.3g}, {window[1]:.3g}]: $T \propto t^{{{exponent:.3f}}}$, "
            + exponent_error_text(a.get("T_exponent_jackknife_error"), a.get("jackknife_realizations")))


def draw_fit(ax_T, ax_a, an, summary):
    """The power law fitted on the window the scene gives (analysis.T_fit_window), its line and its
    exponent as a level, with the jackknife error over realizations (none from one realization)."""
    if "T_fit_t" not in an:
        return None
    window, ends = an["T_fit_t"][:], an["T_fit_T"][:]
    a = summary.get("analysis", {})
    exponent = a.get("T_exponent", attr(an, "T_exponent"))
    error = a.get("T_exponent_jackknife_error")
    text = fit_label(window, exponent, summary)
    ax_T.plot(window, ends, "-", **FIT, label=text)
    ax_a.plot(window, [exponent, exponent], "-", **FIT, label=text)
    if error is not None:
        ax_a.fill_between(window, exponent - error, exponent + error, color=FIT["color"], alpha=0.2, lw=0)
    return window


def draw_late_law(ax, t, T, an, window, sticky_start):
    """The sticky-gas law: exact for a white-noise start (from where the sticky regime starts), else a
    guide fitted on the fit window."""
    power = attr(an, "T_exponent_theory", -2 / 3)
    start = max(t[0], sticky_start) if sticky_start else t[0]
    amplitude = attr(an, "T_amplitude_exact")
    if amplitude is not None and start < t[-1]:
        tt = np.geomspace(start, t[-1], 50)
        ax.plot(tt, amplitude * tt ** power, **EXACT,
                label=f"exact: late-time law of the sticky gas from this white noise, {power_law(amplitude, power)}")
    elif window is not None:
        draw_guide(ax, t, T, power, window, (max(t[0], window[0] / 10), t[-1]), "sticky gas")


def draw_early_law(ax, t, T, an, t_dissip, t_stick):
    """Homogeneous cooling t^-2 on [t_dissip, t_stick], where that window holds 3 samples."""
    if not t_dissip or not t_stick or t_stick < 3 * t_dissip:
        return
    if ((t >= t_dissip) & (t <= t_stick)).sum() < 3:
        return
    power = attr(an, "T_cooling_exponent_theory", -2.0)
    draw_guide(ax, t, T, power, (t_dissip, t_stick), (t_dissip / 3, min(t[-1], 3 * t_stick)),
               "homogeneous cooling", ls="-.")


def draw_levels(ax, an, summary):
    """The local exponent's theory levels where their laws hold for the scene: elastic 0 and homogeneous
    cooling -2 (crossovers), sticky gas -2/3 (sticky_cooling); else the words that there is none."""
    levels, names = [], []
    if theory(summary, "crossovers"):
        levels += [0.0, attr(an, "T_cooling_exponent_theory", -2.0)]
        names += ["0 (elastic)", "-2 (homogeneous cooling)"]
    if theory(summary, "sticky_cooling"):
        levels.append(attr(an, "T_exponent_theory", -2 / 3))
        names.append("-2/3 (sticky gas)")
    for k, level in enumerate(levels):
        ax.axhline(level, ls="--", **GUIDE, label="theory: exponent " + ", ".join(names) if k == 0 else None)
    if not levels:
        ax.text(0.02, 0.04, no_theory_text(summary, "sticky_cooling"), transform=ax.transAxes, fontsize=8,
                color="0.3")
    exponent_ticks(ax, levels)


def exponent_ticks(ax, levels):
    """Ticks of the exponent axis, the theory levels among them, as fractions."""
    ticks = sorted(set([-2.0, -1.5, -1.0, 0.0] + list(levels)))
    ax.set_yticks(ticks, [fraction(tick) for tick in ticks])


def draw_crossovers(axes, t_dissip, t_stick, t):
    for value, name, colour in [(t_dissip, r"$t_{dissip} = 1/\epsilon$", "tab:green"),
                                (t_stick, r"$t_{stick} = \epsilon^{-3/2}$", "tab:purple")]:
        if value and t[0] < value < t[-1]:
            for ax in axes:
                ax.axvline(value, color=colour, ls=":", lw=1.2, label=f"theory: {name} = {value:.3g}")


def draw_local_exponent(ax, p, ok):
    alpha = p["analysis/T_local_exponent"][:][ok]
    ax.plot(p["t"][:][ok], alpha, **DATA, label=PARTICLES_LABEL)
    finite = alpha[np.isfinite(alpha)]
    if finite.size:
        ax.set_ylim(min(-2.3, finite.min() - 0.1), max(0.3, finite.max() + 0.1))


def figure_temperature(f, summary):
    """The figure of a run's T(t), or None when there are fewer than two samples."""
    p = f["particles"]
    t, T = p["t"][:], p["T"][:]
    ok = (t > 0) & (T > 0)
    if ok.sum() < 2:
        return None
    err = p["T_stderr"][:][ok] if "T_stderr" in p else None
    t, T = t[ok], T[ok]
    an = p["analysis"] if "analysis" in p else {}
    fig, (ax_T, ax_a) = plt.subplots(2, 1, figsize=(8, 8), sharex=True, gridspec_kw={"height_ratios": [3, 2]})
    ax_T.errorbar(t, T, yerr=err, **DATA, label=PARTICLES_LABEL)
    t_dissip, t_stick = regime_times(summary)
    if len(an):
        window = draw_fit(ax_T, ax_a, an, summary)
        if theory(summary, "sticky_cooling"):
            draw_late_law(ax_T, t, T, an, window, sticky_regime_start(summary))
        if theory(summary, "crossovers"):
            draw_early_law(ax_T, t, T, an, t_dissip, t_stick)
        draw_levels(ax_a, an, summary)
    if "analysis/T_local_exponent" in p:
        draw_local_exponent(ax_a, p, ok)
    if theory(summary, "crossovers"):
        draw_crossovers((ax_T, ax_a), t_dissip, t_stick, t)
    ax_T.set_xscale("log")
    ax_T.set_yscale("log")
    ax_T.set_ylim(T.min() / 3, T.max() * 3)
    ax_T.set_ylabel(label(T_NAME, unit(p["T"])))
    ax_a.set_ylabel(label(ALPHA_NAME, "1"))
    ax_a.set_xlabel(label(TIME_NAME, unit(p["t"])))
    ax_T.set_title(r"temperature $T = \langle v^2\rangle - \langle v\rangle^2$ (mass weighted) and its local exponent",
                   fontsize=10)
    finish(fig, (ax_T, ax_a), columns=1)
    return fig
