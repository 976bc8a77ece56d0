"""fields.png: every solver's velocity and density at the comparison time,
each in the label and colour of its registration, the exact solution black and
dashed, the particles where they deposited mass (cells without mass hold an
interpolated velocity: not data, not drawn), the counted clusters and shocks
(without a comparison, the heaviest cluster), and the initial condition."""
import matplotlib.pyplot as plt
import numpy as np

from .common import CLUSTER, EXACT, INITIAL, PARTICLES, SHOCK, attr, finish, label, solver_style, unit
from .decimate import decimated


def solvers(f):
    """The solver groups with fields, the exact one last (drawn on top)."""
    c = f["continuum"]
    groups = [(name, c[name]) for name in c if "x" in c[name]]
    return sorted(groups, key=lambda item: bool(attr(item[1], "exact", 0)))


def _range(values):
    finite = values[np.isfinite(values)]
    return (finite.max() - finite.min()) if finite.size else 0.0


def initial_fits_beside(f, groups):
    """Whether v0 can share the velocity panel: its range at most 1.5x that of the
    exact field (else of the narrowest), so that it does not squash the fields."""
    if "initial/cells/v" not in f or not groups:
        return False
    exact = [g for _, g in groups if attr(g, "exact", 0)]
    final = _range(exact[0]["v"][:]) if exact else min(_range(g["v"][:]) for _, g in groups)
    return _range(f["initial/cells/v"][:]) <= 1.5 * max(final, 1e-300)


def density_scale(ar):
    """Log where every drawn density is positive, else symlog (linear through 0 up to 1)."""
    values = [line.get_ydata() for line in ar.get_lines() if len(line.get_ydata())]
    lowest = min((np.nanmin(v) for v in values), default=0.0)
    if lowest > 0:
        ar.set_yscale("log")
    else:
        ar.set_yscale("symlog", linthresh=1.0)
        ar.set_ylim(bottom=min(lowest, 0.0))  # no empty negative decade from the margins


def window_with_shocks(f, groups, most=50):
    """(x_max, text) showing about `most` shocks of the exact solver when it has
    more than twice as many (a crowded ring), else None."""
    exact = [(name, g) for name, g in groups if attr(g, "exact", 0) and "shocks/x" in g]
    if not exact:
        return None
    name, g = exact[0]
    n, x = len(g["shocks/x"]), g["x"][:]
    if n <= 2 * most:
        return None
    length = x[-1] + (x[1] - x[0]) / 2
    x_max = length * most / n
    return x_max, f"x < {x_max:.4g} of the {length:.4g} shown: about {most} of the {n} shocks of {name}"


def draw_solvers(av, ar, groups):
    for name, g in groups:
        style = solver_style(g, name)
        decimated(av.plot(g["x"][:], g["v"][:], **style))
        if has_density(g):  # solvers without a density are absent from the density panel
            decimated(ar.plot(g["x"][:], g["rho"][:], **style))


def draw_particles(av, ar, cmp):
    """The particles' own cells: v where mass was deposited, rho where it is > 0."""
    x = cmp["x"][:]
    occupied = cmp["occupied"][:] > 0 if "occupied" in cmp else cmp["rho_particles"][:] > 0
    text = "particles: momentum / mass and mass / dx in the cells holding mass"
    decimated(av.plot(x[occupied], cmp["v_particles"][:][occupied], **PARTICLES, label=text))
    decimated(ar.plot(x[occupied], cmp["rho_particles"][:][occupied], **PARTICLES, label=text))


def draw_clusters_and_shocks(ar, cmp, solver):
    """The clusters and shocks the comparison counts (mass >= min_mass), along the foot of the density panel."""
    min_mass = attr(cmp, "min_mass", 0.0)
    for kind, mass, style, text in [
            ("clusters", "clusters_m", CLUSTER, f"clusters of the gas, mass >= {min_mass:.3g}"),
            ("shocks", "shocks_mass", SHOCK, f"shocks of {solver}, mass >= {min_mass:.3g}")]:
        if kind + "_x" in cmp:
            xs = cmp[kind + "_x"][:][cmp[mass][:] >= min_mass]  # at the foot of the panel
            ar.plot(xs, np.full_like(xs, 0.04), **style, label=text, transform=ar.get_xaxis_transform(), zorder=6)


def draw_heaviest_cluster(av, ar, summary, t):
    """Without a comparison, the particles' heaviest cluster (summary analysis.heaviest_cluster_*)
    at (x, v) and at the foot of the density panel, when the particles stopped at the fields' time."""
    a, p = summary.get("analysis", {}), summary.get("particles", {})
    stop = p.get("stop_time")
    if "heaviest_cluster_x" not in a or stop is None or abs(stop - t) > 1e-9 * max(abs(t), 1.0):
        return
    x, m, v = a["heaviest_cluster_x"], a["heaviest_cluster_m"], a["heaviest_cluster_v"]
    text = f"heaviest cluster of the gas: mass {m:.4g}, velocity {v:.4g}"
    av.plot([x], [v], **dict(CLUSTER, ms=9), label=text, zorder=6)
    if ar is not None:
        ar.plot([x], [0.04], **dict(CLUSTER, ms=9), label=text, transform=ar.get_xaxis_transform(), zorder=6)


def draw_initial(av, ar, f, beside):
    """v0 beside the fields when it fits their scale (else in its own panel), rho0 always."""
    if "initial/cells/x" not in f:
        return
    x0 = f["initial/cells/x"][:]
    if beside:
        decimated(av.plot(x0, f["initial/cells/v"][:], **INITIAL, label="initial condition (t = 0)"))
    if ar is not None:
        decimated(ar.plot(x0, f["initial/cells/rho"][:], **INITIAL, label="initial condition (t = 0)"))


def error_pairs(groups):
    """(name, group, exact group) of every solver on the exact solver's grid: their error can be drawn."""
    exact = [g for _, g in groups if attr(g, "exact", 0)]
    if not exact:
        return []
    x = exact[0]["x"][:]
    return [(name, g, exact[0]) for name, g in groups
            if not attr(g, "exact", 0) and g["x"].shape == x.shape and np.allclose(g["x"][:], x)]


def draw_errors(ae, pairs):
    """v - v_exact of each solver on the exact grid: a solver that lies under the exact line shows its error here."""
    for name, g, exact in pairs:
        style = solver_style(g, name)
        decimated(ae.plot(g["x"][:], g["v"][:] - exact["v"][:], **style))
    ae.axhline(0.0, **dict(EXACT, lw=0.8))
    ae.set_ylabel(label(r"$v - v_{exact}$", unit(exact["v"])))
    ae.set_title("error of each solver: numerical minus exact velocity", fontsize=9)


def has_density(g):
    return "rho" in g and g["rho"].shape == g["x"].shape


def figure_fields(f, summary):
    groups = solvers(f)
    if not groups:
        return None
    cmp = f["compare"] if "compare" in f and "x" in f["compare"] else None
    dense = [g for _, g in groups if has_density(g)]
    beside = initial_fits_beside(f, groups)
    separate = "initial/cells/v" in f and not beside
    pairs = error_pairs(groups)
    heights = ([1] if separate else []) + [2] + ([1.2] if pairs else []) + ([2] if dense or cmp is not None else [])
    fig, axes = plt.subplots(len(heights), 1, figsize=(10, 1.6 * sum(heights) + 0.8), sharex=True,
                             gridspec_kw={"height_ratios": heights}, squeeze=False)
    axes = list(axes[:, 0])
    a0 = axes.pop(0) if separate else None
    ae = axes.pop(1) if pairs else None
    av, ar = axes[0], axes[1] if len(axes) > 1 else None
    if separate:
        decimated(a0.plot(f["initial/cells/x"][:], f["initial/cells/v"][:], color="0.45", lw=0.5))
        a0.set_ylabel(label("$v_0$", unit(f["initial/cells/v"])))
        a0.set_title("initial condition (t = 0): velocity, cell averages", fontsize=9)
    draw_initial(av, ar, f, beside)
    draw_solvers(av, ar, groups)
    if ae is not None:
        draw_errors(ae, pairs)
    some = groups[0][1]
    t = attr(some, "t", 0)
    # Particles stopped early are compared at their own time (the continuum run
    # again there): not drawn over fields of another time.
    t_compared = attr(cmp, "t", t) if cmp is not None else t
    elsewhen = abs(t_compared - t) > 1e-9 * max(abs(t), 1.0)
    if cmp is not None and not elsewhen:
        draw_particles(av, ar, cmp)
        draw_clusters_and_shocks(ar, cmp, summary.get("compare", {}).get("solver", "the compared solver"))
    if cmp is None:
        draw_heaviest_cluster(av, ar, summary, t)
    av.set_ylabel(label("velocity $v$", unit(some["v"])))
    title = f"fields at t = {t:.4g}"
    if elsewhen:
        title += f"; particles stopped at t = {t_compared:.4g} (see clusters.png)"
    window = window_with_shocks(f, groups)
    if window is not None:
        av.set_xlim(0, window[0])
        title += f" ({window[1]})"
    if ar is not None:
        density_scale(ar)
        rho = dense[0]["rho"] if dense else cmp["rho_particles"]
        ar.set_ylabel(label(r"density $\rho$", unit(rho)))
    (ar or av).set_xlabel(label("position $x$", unit(some["x"])))
    av.set_title(title, fontsize=10)
    finish(fig, [a for a in (a0, av, ae, ar) if a is not None], columns=2)
    return fig
