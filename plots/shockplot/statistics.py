"""The figure page of the shock statistics (statistics.png), drawn from
statistics.csv only: the clusters' mass distribution (clusters per realization
in each bin of 1.5, 2.5, 4.5, ... particles, per particle of bin width) with the
exact shock-mass law, the mass-weighted distribution of z = (v - U) t^(1/3) with
the exact cluster velocity law, and the distribution of the gaps between
neighbouring clusters (no exact law). Error bars: the jackknife over
realizations; the exact laws drawn as lines, the data as points. Written by
`shockgas stats` (plots/plot_statistics.py) and, for a scene with [statistics],
with the run's other pictures (drawing.py)."""
import math
import os

import matplotlib.pyplot as plt

from .common import EXACT
from .run_files import number, read_csv
from .saving import save

CSV = "statistics.csv"
PNG = "statistics.png"


def rows_of(table, quantity):
    """The rows of one quantity: (low, high, value, error, exact) with nan where empty."""
    return [(r["bin_low"], r["bin_high"], r["value"], r["error"], r["exact"]) for r in table
            if r["quantity"] == quantity]


def one_row(table, quantity):
    rows = rows_of(table, quantity)
    return rows[0] if rows else (math.nan,) * 5


def points(ax, rows, per_width, label, log_x=False):
    """The data as points with error bars at the bins' centres, each value divided
    by its bin width when per_width (a density)."""
    xs, ys, es = [], [], []
    rows = [r for r in rows if not math.isnan(r[2])]
    if not rows:
        ax.text(0.5, 0.5, "none: fewer than two clusters in every realization", transform=ax.transAxes,
                ha="center", fontsize=9)
        return
    for low, high, value, error, _ in rows:
        width = high - low if per_width else 1.0
        xs.append(math.sqrt(low * high) if log_x else (low + high) / 2)
        ys.append(value / width)
        es.append(0.0 if math.isnan(error) else error / width)
    ax.errorbar(xs, ys, yerr=es, fmt="o", ms=3.5, capsize=2, color="tab:blue", label=label, zorder=3)


def exact_steps(ax, rows, per_width, label):
    """The exact law on the same bins, as a line (steps over the bins)."""
    if not rows or all(math.isnan(r[4]) for r in rows):
        return False
    xs, ys = [], []
    for low, high, _, _, exact in rows:
        width = high - low if per_width else 1.0
        xs += [low, high]
        ys += [exact / width, exact / width]
    ax.plot(xs, ys, **dict(EXACT, lw=1.2, zorder=2), label=label)
    return True


def below(ax):
    """The panel's legend under its axes, clear of the data (none where nothing is drawn)."""
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.16), frameon=False)


def with_law(ax, rows, per_width, data_label, law_label, log_x=False):
    """The data as points and, where the start has one, the exact law as a line;
    else a note that there is none."""
    points(ax, [r for r in rows if r[2] > 0] if log_x else rows, per_width, data_label, log_x=log_x)
    if not exact_steps(ax, rows, per_width, law_label):
        ax.text(0.03, 0.03, "no exact law for this start", transform=ax.transAxes, fontsize=8)


def mass_panel(ax, table, realizations):
    with_law(ax, rows_of(table, "mass"), True, f"clusters, {realizations} realizations",
             "exact shock-mass law (white noise)", log_x=True)
    ax.set(xscale="log", yscale="log", xlabel="cluster mass m [particles]",
           ylabel="clusters per realization per unit mass [1/particle]", title="Masses")
    below(ax)


def velocity_panel(ax, table, realizations):
    rows = rows_of(table, "velocity")
    with_law(ax, rows, False, f"clusters, {realizations} realizations", "exact cluster velocity law (white noise)")
    ax.set(yscale="log", xlabel=r"$z = (v - U)\,t^{1/3}$ [length/time$^{2/3}$]",
           ylabel=r"mass fraction per unit $z$ [time$^{2/3}$/length]", title="Velocities, mass weighted")
    positive = [r[2] for r in rows if r[2] > 0]  # nan > 0 is False
    if positive:
        ax.set_ylim(min(positive) / 3, max(positive) * 3)
    below(ax)


def spacing_panel(ax, table, realizations):
    rows = rows_of(table, "spacing")
    points(ax, rows, False, f"gaps, {realizations} realizations")
    ax.set(xlabel="gap between neighbouring clusters [mean gaps]", ylabel="fraction of gaps per unit gap [1]",
           title="Spacing (no exact law in shockgas)")
    ax.set_ylim(bottom=0)
    below(ax)


def figure(directory):
    """The statistics page of DIR (its statistics.csv), not yet saved."""
    text = ("quantity", "unit", "bin_unit")  # the columns of words; the others are numbers
    table = [{k: v if k in text else number(v) for k, v in row.items()}
             for row in read_csv(os.path.join(directory, CSV))]
    count = one_row(table, "count")
    correlation = one_row(table, "mass_speed_correlation")
    realizations = int(one_row(table, "realizations")[2])
    fig, axes = plt.subplots(1, 3, figsize=(15, 5.2))
    mass_panel(axes[0], table, realizations)
    velocity_panel(axes[1], table, realizations)
    spacing_panel(axes[2], table, realizations)
    error = "" if math.isnan(count[3]) else f" ± {count[3]:.3g}"
    exact = "" if math.isnan(count[4]) else f" (exact {count[4]:.4g})"
    r_error = "" if math.isnan(correlation[3]) else f" ± {correlation[3]:.2g}"
    r_text = "not defined" if math.isnan(correlation[2]) else f"{correlation[2]:.3f}{r_error}"
    fig.suptitle(f"Shock statistics: {count[2]:.4g}{error} clusters of ≥ 2 particles per realization{exact}; "
                 f"correlation of mass and |v − U| {r_text}", fontsize=11)
    return fig


def draw_statistics(directory):
    """Writes DIR/statistics.png from DIR/statistics.csv, whole or not at all."""
    save(figure(directory), os.path.join(directory, PNG), CSV)
