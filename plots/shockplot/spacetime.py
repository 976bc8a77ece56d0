"""spacetime.png: the world lines of the particles (realization 0)."""
import matplotlib.pyplot as plt
import numpy as np

from .common import label, unit


def shown_lines(drawn):
    """Which particles the drawn labels are, in words."""
    gaps = np.diff(drawn)
    if len(drawn) == drawn[-1] + 1:
        return "every particle"
    if len(gaps) and np.all(gaps == gaps[0]):
        return f"every {gaps[0]}th particle"
    return f"{len(drawn)} particles, about every {np.mean(gaps):.3g}th"


def figure_spacetime(f):
    s = f["particles/spacetime"]
    t, x = s["t"][:], s["x"][:]
    # the columns' particles; a file of layout 1.0 holds every particle, without labels
    labels = s["label"][:] if "label" in s else np.arange(x.shape[1])
    fig, ax = plt.subplots(figsize=(6.5, 6.5))
    step = max(1, x.shape[1] // 400)
    span = np.nanmax(x) - np.nanmin(x)
    for j in range(0, x.shape[1], step):
        xs = x[:, j].copy()
        xs[1:][np.abs(np.diff(xs)) > 0.5 * span] = np.nan  # no wrap-around lines on the ring
        ax.plot(xs, t, "k-", lw=0.3)
    ax.set_xlabel(label("position $x$", unit(s["x"])))
    ax.set_ylabel(label("time $t$", unit(s["t"])))
    ax.set_title(f"space-time diagram: world lines of {shown_lines(labels[::step])} (realization 0)", fontsize=10)
    fig.tight_layout()
    return fig
