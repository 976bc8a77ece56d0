"""velocity_distribution.png: the scaled velocity distribution Phi(z) of the
particles, z = (v - <v>) t^(1/3), at the late sample times, over the exact
mass-weighted law of the sticky gas when the start is white noise."""
import matplotlib.pyplot as plt
import numpy as np

from .common import EXACT, finish, label, unit

Z_NAME = r"$z = (v - \langle v\rangle)\,t^{1/3}$"
PHI_NAME = r"$\Phi(z)$"


def late_rows(t, count=4):
    """Up to `count` sample times spread over the late half of the record."""
    return np.unique(np.linspace(len(t) // 2, len(t) - 1, count).astype(int))


def draw_exact(ax, z, exact):
    """The exact law on the histogram's bins (bin means), as a step curve."""
    width = z[1] - z[0] if len(z) > 1 else 1.0
    edges = np.append(z - width / 2, z[-1] + width / 2)
    ax.stairs(np.where(exact > 0, exact, np.nan), edges, **EXACT,
              label="exact: mass-weighted law of the sticky gas (r = 0) from this white noise, bin means")


def axes_labels(ax, h, rows):
    """Log density down to a decade below the lowest measured value, z over the
    measured range and half a unit beyond (the exact law goes further)."""
    ax.set_yscale("log")
    values = np.concatenate([r[r > 0] for r in rows]) if rows else np.zeros(0)
    if values.size:
        ax.set_ylim(bottom=values.min() / 10)
        z = h["z"][:]
        reach = max(np.abs(z[r > 0]).max() for r in rows if (r > 0).any())
        ax.set_xlim(-reach - 0.5, reach + 0.5)
    ax.set_xlabel(label(Z_NAME, unit(h["z"])))
    ax.set_ylabel(label(PHI_NAME, unit(h["density"])))


def figure_distribution(f):
    h = f["particles/histogram"]
    t = h["t"][:]
    if len(t) == 0:
        return None
    z, density = h["z"][:], h["density"][:]
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    rows = late_rows(t)
    for k, colour in zip(rows, plt.cm.viridis(np.linspace(0.1, 0.85, len(rows)))):
        ax.plot(z, np.where(density[k] > 0, density[k], np.nan), "o-", ms=2.5, lw=0.9, color=colour,
                label=f"particles at t = {t[k]:.3g}")
    if "exact" in h:
        draw_exact(ax, z, h["exact"][:])
    axes_labels(ax, h, [density[k] for k in rows])
    ax.set_title(r"scaled velocity distribution $P(v, t)\,t^{-1/3} = \Phi(z)$ (mass weighted)", fontsize=10)
    finish(fig, [ax], columns=2)
    return fig
