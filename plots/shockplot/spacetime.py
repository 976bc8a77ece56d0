"""spacetime.png: the world lines of the particles (realization 0)."""
import matplotlib.pyplot as plt
import numpy as np

from .common import label, unit


def figure_spacetime(f):
    s = f["particles/spacetime"]
    t, x = s["t"][:], s["x"][:]
    fig, ax = plt.subplots(figsize=(6.5, 6.5))
    step = max(1, x.shape[1] // 400)
    span = np.nanmax(x) - np.nanmin(x)
    for j in range(0, x.shape[1], step):
        xs = x[:, j].copy()
        xs[1:][np.abs(np.diff(xs)) > 0.5 * span] = np.nan  # no wrap-around lines on the ring
        ax.plot(xs, t, "k-", lw=0.3)
    ax.set_xlabel(label("position $x$", unit(s["x"])))
    ax.set_ylabel(label("time $t$", unit(s["t"])))
    shown = "every particle" if step == 1 else f"every {step}th particle"
    ax.set_title(f"space-time diagram: world lines of {shown} (realization 0)", fontsize=10)
    fig.tight_layout()
    return fig
