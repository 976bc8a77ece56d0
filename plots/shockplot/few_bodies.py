"""temperature.png of a few bodies (fewer than GAS_PARTICLES particles, e.g. the
three-particle collapse): T(t) of each run on linear axes, where T reaching 0
(a complete collapse) stays visible, without the gas's laws, guides or local
exponent, which are statistical and do not apply."""
import matplotlib.pyplot as plt
import numpy as np

from .common import GAS_PARTICLES, attr, finish, label, unit


def _series(f):
    """(label, t, T, T dataset) of the run itself or of every variant of a sweep."""
    if "sweep" in f:
        groups = [(attr(f["sweep"][k], "label", k), f["sweep"][k]) for k in sorted(f["sweep"], key=int)]
    else:
        groups = [("particles", f)]
    return [(name, g["particles/t"][:], g["particles/T"][:], g["particles/T"]) for name, g in groups
            if "particles/T" in g]


def figure_few_bodies(f):
    series = _series(f)
    if not series:
        return None
    fig, ax = plt.subplots(figsize=(7.5, 5))
    colours = plt.cm.tab10(np.arange(len(series)) % 10)
    for k, ((name, t, T, _), colour) in enumerate(zip(series, colours)):
        # markers of falling size, so that runs on the same values stay visible
        ax.plot(t, T, "-", marker="osD^v"[k % 5], ms=9 - 1.5 * (k % 5), mfc="none", lw=1, color=colour, label=name)
    ax.set_ylim(bottom=0)
    ax.set_xlabel(label("time $t$", unit(series[0][3].parent["t"])))
    ax.set_ylabel(label(r"temperature $T = \langle v^2\rangle - \langle v\rangle^2$", unit(series[0][3])))
    ax.set_title(f"temperature of a few bodies (fewer than {GAS_PARTICLES}: the laws of the gas do not apply)",
                 fontsize=10)
    finish(fig, [ax], columns=2)
    return fig
