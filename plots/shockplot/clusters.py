"""clusters.png: the clusters of the gas -- the number of those of k or more
particles (particles.min_cluster_particles, 2 by default) in time against
N t^(-2/3) (exact for a white-noise start: the shocks of Burgers turbulence),
their masses against the exact shock-mass law, and their positions and masses
against the shocks of the compared solver."""
import matplotlib.pyplot as plt
import numpy as np

from .common import (CLUSTER, EXACT, GUIDE, SHOCK, attr, draw_guide, finish, is_gas, label, sticky_regime_start,
                     theory, unit)
from .log_ticks import TextLogFormatter

DATA = {"color": "tab:blue", "marker": "o", "ms": 3, "lw": 1, "zorder": 3}


def minor_labels():
    """Labels on the minor ticks of a log axis that spans less than two decades."""
    return TextLogFormatter(labelOnlyBase=False, minor_thresholds=(2, 0.4))


def _count_in_time(ax, f, summary):
    """The engine's count of clusters of >= k particles at the sample times
    (k = particles.min_cluster_particles), with the exact count of the shocks
    heavier than k - 1/2 particles of a white-noise start (else a fitted
    N t^(-2/3) guide), and the comparison's count of clusters and exact shocks
    heavier than its threshold at its time."""
    p = f["particles"]
    k = summary.get("particles", {}).get("min_cluster_particles", 2)
    t, n = p["t"][:], p["n_clusters"][:]
    ok = (t > 0) & (n > 0)
    t, n = t[ok], n[ok]
    err = p["n_clusters_stderr"][:][ok] if "n_clusters_stderr" in p else None
    merged = summary.get("particles", {}).get("r") == 0
    criteria = ("merged bodies" if merged
                else r"criteria at that time: gap < max($a/2$, $\sqrt{\delta t a}$), |dv| < 5$\delta$")
    ax.errorbar(t, n, yerr=err, **DATA, label=f"particles: clusters of ≥ {k} particles at each sample ({criteria})")
    N = summary.get("initial", {}).get("N")
    an = p["analysis"] if "analysis" in p else None
    coefficient = attr(an, "n_shocks_exact_coefficient") if an is not None else None
    sticky = sticky_regime_start(summary)
    start = max(t[0], sticky) if sticky else t[0]
    # The laws are statistical (none over a few bodies) and hold from 10 t_stick (theory.shock_count).
    gas = is_gas(summary) and theory(summary, "shock_count") is not None
    exact_count = an["n_clusters_exact"][:][ok] if an is not None and "n_clusters_exact" in an else None
    if exact_count is not None and start < t[-1] and gas:
        late = t >= start
        ax.plot(t[late], exact_count[late], **EXACT,
                label=f"exact: shocks heavier than {k - 0.5:g} particles of Burgers turbulence from this "
                      "white noise (shock-mass law)")
    elif coefficient is not None and N and start < t[-1] and gas:
        tt = np.geomspace(start, t[-1], 50)
        ax.plot(tt, coefficient * tt ** (-2 / 3), **EXACT,
                label=rf"exact: shocks of Burgers turbulence from this white noise, ${coefficient / N:.4g}\,N t^{{-2/3}}$"
                      " (those lighter than a particle included)")
    elif an is not None and "T_fit_t" in an and gas:
        window = an["T_fit_t"][:]
        draw_guide(ax, t, n, -2 / 3, window, (max(t[0], window[0] / 10), t[-1]), "N t^(-2/3) law")
    _eligible_at_the_comparison(ax, summary)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.yaxis.set_minor_formatter(minor_labels())  # a count over less than a decade still reads
    ax.set_xlabel(label("time $t$", unit(p["t"])))
    ax.set_ylabel(label(f"clusters of ≥ {k} particles", unit(p["n_clusters"])))
    ax.set_title("clusters in time", fontsize=10)


def _eligible_at_the_comparison(ax, summary):
    c = summary.get("compare", {})
    if "t" not in c or "n_clusters" not in c:
        return
    m = c.get("min_mass", 0)
    if c["n_clusters"] > 0:  # (none to draw on a log axis otherwise)
        ax.plot([c["t"]], [c["n_clusters"]], **dict(CLUSTER, ms=8),
                label=f"comparison: clusters of mass >= {m:.3g} (criteria at its time)")
    # One number at one time: a marker alone (a line would claim a range of times), where the
    # white-noise law holds at that time (theory.shock_count: not for a run that stopped early).
    if "n_shocks_exact" in c and theory(summary, "shock_count") is not None:
        ax.plot([c["t"]], [c["n_shocks_exact"]], **dict(EXACT, ls="none"), marker="D", mfc="none", ms=8,
                label=f"exact: expected shocks of mass >= {m:.3g} at that time")


def _mass_distribution(ax, cmp, law_holds):
    edges, count = cmp["cluster_mass_edges"][:], cmp["cluster_mass_count"][:]
    width = np.diff(edges)
    centre = np.sqrt(edges[:-1] * edges[1:])
    some = count > 0
    ax.errorbar(centre[some], (count / width)[some], yerr=(np.sqrt(count) / width)[some], color="tab:blue",
                marker="o", ms=4, ls="none", label="particles: clusters per unit mass, ± Poisson error")
    if "cluster_mass_exact" in cmp and law_holds:  # the shock-mass law where it holds at that time
        exact = cmp["cluster_mass_exact"][:] / width
        ax.stairs(np.where(exact > 0, exact, np.nan), edges, **EXACT,
                  label="exact: shocks of Burgers turbulence from this white noise (shock-mass law), bin means")
    min_mass = attr(cmp, "min_mass", 0.0)
    ax.axvline(min_mass, ls=":", **GUIDE, label=f"smallest mass the comparison counts: {min_mass:.3g}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(label("cluster mass $m$", unit(cmp["cluster_mass_edges"])))
    ax.set_ylabel(label("clusters per unit mass $dn/dm$", "1/" + unit(cmp["cluster_mass_edges"])))
    ax.set_title("cluster masses at the comparison", fontsize=10)


def _pairs(cmp):
    if "matched_shock" not in cmp:
        return np.zeros(0, int), np.zeros(0, int)
    return cmp["matched_shock"][:].astype(int), cmp["matched_cluster"][:].astype(int)


def _positions(ax, cmp, solver):
    """Clusters and shocks of mass >= min_mass at (x, m); matched pairs joined."""
    min_mass = attr(cmp, "min_mass", 0.0)
    cx, cm = cmp["clusters_x"][:], cmp["clusters_m"][:]
    sx, sm = cmp["shocks_x"][:], cmp["shocks_mass"][:]
    shocks, clusters = _pairs(cmp)
    for k, (i, j) in enumerate(zip(shocks, clusters)):
        ax.plot([sx[i], cx[j]], [sm[i], cm[j]], "-", color="0.6", lw=0.8,
                label="a matched pair (shock to cluster)" if k == 0 else None)
    lone_c = np.setdiff1d(np.flatnonzero(cm >= min_mass), clusters)
    lone_s = np.setdiff1d(np.flatnonzero(sm >= min_mass), shocks)
    ax.plot(cx[clusters], cm[clusters], **CLUSTER, label="cluster of the gas")
    ax.plot(sx[shocks], sm[shocks], **SHOCK, label=f"shock of {solver}")
    ax.plot(cx[lone_c], cm[lone_c], **dict(CLUSTER, mfc="none"), label="cluster without a shock")
    ax.plot(sx[lone_s], sm[lone_s], **dict(SHOCK, mfc="none"), label=f"shock of {solver} without a cluster")
    ax.axhline(min_mass, ls=":", **GUIDE, label=f"smallest mass the comparison counts: {min_mass:.3g}")
    ax.set_yscale("log")
    ax.yaxis.set_minor_formatter(minor_labels())
    ax.set_xlabel(label("position $x$", unit(cmp["clusters_x"])))
    ax.set_ylabel(label("mass $m$", unit(cmp["clusters_m"])))
    ax.set_title(f"clusters against shocks at t = {attr(cmp, 't', 0):.4g}: positions and masses", fontsize=10)


def figure_clusters(f, summary):
    in_time = "particles/n_clusters" in f and (f["particles/n_clusters"][:] > 0).any()
    cmp = f["compare"] if "compare/cluster_mass_edges" in f else None
    if not in_time and cmp is None:
        return None
    solver = summary.get("compare", {}).get("solver", "the continuum")
    if cmp is None:
        fig, ax = plt.subplots(figsize=(7.5, 5.5))
        panels = [ax]
        _count_in_time(ax, f, summary)
    else:
        fig = plt.figure(figsize=(11, 9))
        grid = fig.add_gridspec(2, 2)
        top = [fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1])]
        bottom = fig.add_subplot(grid[1, :])
        if in_time:
            _count_in_time(top[0], f, summary)
        else:
            top[0].set_visible(False)
        _mass_distribution(top[1], cmp, theory(summary, "shock_count") is not None)
        _positions(bottom, cmp, solver)
        panels = top + [bottom]
    if cmp is not None:
        fig.suptitle("clusters of the gas")
    finish(fig, panels, columns=2 if cmp is not None else 1)
    return fig
