"""evolution.png (a run with [output] animation = true and continuum solvers):
how the measured solver's wave evolves over the frames -- the breaking line
-1 / min dv/dx = t* - t before the first shock against the exact t*, the
amplitude's decay with its fit, the lobes' areas against their conservation,
and the number of shocks."""
import matplotlib.pyplot as plt
import numpy as np

from .common import EXACT, GUIDE, attr, exponent_error_text, finish, label, note_no_theory, theory, unit

DATA = {"color": "tab:blue", "marker": "o", "ms": 4, "zorder": 3}
FIT = {"color": "tab:red", "lw": 2.5, "alpha": 0.7, "zorder": 4}


def _breaking(ax, e, t, s, t_unit):
    """-1 / min dv/dx over the smooth frames, and the exact line t* - t."""
    smooth = np.cumsum(e["shocks"][:] * (t > 0)) == 0
    slope = e["steepest_slope"][:]
    ok = smooth & (slope < 0)
    if ok.sum() < 2:
        return False
    fitted = ok & (e["breaking_fit"][:] > 0)
    ax.plot(t[fitted], -1 / slope[fitted], ls="none", **DATA, label="measured: -1 / min dv/dx (fitted)")
    rest = ok & ~fitted
    if rest.any():
        ax.plot(t[rest], -1 / slope[rest], ls="none", mfc="none", **DATA,
                label="measured: slope too steep for the grid (not fitted)")
    theory = s.get("breaking_time_theory")
    if theory is not None:
        tt = np.linspace(0, theory, 50)
        ax.plot(tt, theory - tt, **EXACT, label=f"exact: t* - t, t* = 1 / max(-v0') = {theory:.4g}")
    measured = s.get("shock_formation_time")
    if measured is not None:
        ax.axvline(measured, color="tab:red", lw=1, label=f"measured breaking time t* = {measured:.4g}")
    ax.set_xlim(0, max(t[ok].max(), theory or 0) * 1.05)
    ax.set_ylim(0, None)
    ax.set_xlabel(label("time $t$", t_unit))
    ax.set_ylabel(label("$-1 / \\min\\, \\partial_x v$", t_unit))
    ax.set_title("wave breaking: the steepest slope blows up at t*", fontsize=10)
    return True


def _time_axis(ax, t_unit, log):
    if log:
        ax.set_xscale("log")
    ax.set_xlabel(label("time $t$", t_unit))


DECAY_LAWS = [("n_wave_decay", "N-wave $t^{-1/2}$"), ("sawtooth_decay", "periodic sawtooth $t^{-1}$")]


def decay_title(ax, summary):
    """The decay law that holds for the scene, with its window; or no theory, with why in the panel."""
    for law, text in DECAY_LAWS:
        scope = theory(summary, law)
        if scope:
            return f"decay (theory: {text} on [{scope['window'][0]:.3g}, {scope['window'][1]:.3g}])"
    pulse = "isolated pulse" in summary.get("theory", {}).get("sawtooth_decay", {}).get("why", "")
    note_no_theory(ax, summary, "n_wave_decay" if pulse else "sawtooth_decay")  # the law of the wave's kind
    return "decay: no theory for this scene"


def _amplitude(ax, e, t, s, t_unit, summary):
    a = e["amplitude"][:]
    ok = (t > 0) & (a > 0)
    ax.loglog(t[ok], a[ok], "-", lw=1, **DATA, label="measured: amplitude (max v - min v) / 2")
    if "amplitude_fit_t" in e:  # one deterministic run: no error from realizations
        window = e["amplitude_fit_t"][:]
        exponent = s.get("amplitude_exponent", float("nan"))
        ax.loglog(window, e["amplitude_fit"][:], "-", **FIT,
                  label=rf"fit of the amplitude after breaking, on [{window[0]:.3g}, {window[1]:.3g}]: "
                        rf"$t^{{{exponent:.3f}}}$, " + exponent_error_text(None))
    low, high = a[ok].min(), a[ok].max()
    if high - low <= 1e-9 * high:  # constant to rounding: no zoom into the rounding
        ax.set_ylim(np.sqrt(low * high) / 2, np.sqrt(low * high) * 2)
    ax.set_xlabel(label("time $t$", t_unit))
    ax.set_ylabel(label("amplitude", unit(e["amplitude"])))
    ax.set_title(decay_title(ax, summary), fontsize=10)


def _lobes(ax, e, t, t_unit, log, summary):
    keep = t > 0 if log else np.ones_like(t, dtype=bool)
    top = 1.1
    for name, colour, marker, text in [("positive_area", "tab:orange", "o", "lobes above the mean, A+(t) / A+(0)"),
                                       ("negative_area", "tab:purple", "x", "lobes below the mean, A-(t) / A-(0)")]:
        area = e[name][:]
        if area[0] != 0:
            ax.plot(t[keep], area[keep] / area[0], "-", marker=marker, ms=4, color=colour, label=f"measured: {text}")
            top = max(top, 1.05 * np.max(area / area[0]))
    if theory(summary, "lobe_areas"):
        ax.axhline(1.0, ls="--", **GUIDE, label="theory: 1, an isolated wave keeps the area of each lobe")
        ax.set_title("lobe areas", fontsize=10)
    else:
        ax.set_title("lobe areas: no theory for this scene", fontsize=10)
        note_no_theory(ax, summary, "lobe_areas")
    ax.set_ylim(0, top)
    _time_axis(ax, t_unit, log)
    ax.set_ylabel(label("area / initial area", "1"))


def _shocks(ax, e, t, t_unit, log):
    keep = t > 0 if log else np.ones_like(t, dtype=bool)
    ax.step(t[keep], e["shocks"][:][keep], where="post", color="tab:green", label="measured: shocks in each frame")
    ax.set_ylim(0, None)
    _time_axis(ax, t_unit, log)
    ax.set_ylabel(label("shocks", unit(e["shocks"])))
    ax.set_title("number of shocks", fontsize=10)
    ax.yaxis.get_major_locator().set_params(integer=True)


def figure_evolution(f, summary):
    e = f["animation/evolution"]
    t = f["animation/t"][:]
    t_unit = unit(f["animation/t"])
    s = summary.get("evolution", {})
    positive = t[t > 0]
    log = len(positive) > 2 and positive[-1] / positive[0] > 50  # log-spaced frames
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    drawn = [axes[0, 1], axes[1, 0], axes[1, 1]]
    if _breaking(axes[0, 0], e, t, s, t_unit):
        drawn.insert(0, axes[0, 0])
    else:
        axes[0, 0].axis("off")
        axes[0, 0].text(0.5, 0.5, "no breaking to show:\nfewer than two smooth frames before the first shock",
                        ha="center", va="center", transform=axes[0, 0].transAxes, fontsize=10)
    _amplitude(axes[0, 1], e, t, s, t_unit, summary)
    _lobes(axes[1, 0], e, t, t_unit, log, summary)
    _shocks(axes[1, 1], e, t, t_unit, log)
    fig.suptitle(f"the wave in time ({attr(e, 'solver', '')}): breaking, decay, lobes, shocks")
    finish(fig, drawn, columns=2)
    return fig
