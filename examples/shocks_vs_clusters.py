"""Shocks against clusters, from initial velocities of your own.

N particles sit on a ring of length N (unit spacing) with velocities of your
own choosing (here: a long wave with white noise on top). The inelastic
gas (r = 0.5, threshold delta = 1e-2) runs to t, and so does the exact inviscid
continuum (Hopf-Lax) from the same bodies. Its shocks are the gas's clusters
(Ben-Naim et al., PRL 83, 4069, 1999): matched one to one, at the same places,
with about the same masses, and between them the velocity is the ramp of slope
1/t.

    PYTHONPATH=build/python /usr/bin/python3 examples/shocks_vs_clusters.py [OUT_DIR]

writes OUT_DIR/shocks_vs_clusters.png (default: the current directory).
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import shockgas  # noqa: E402

N, T, R, DELTA, CELLS = 10000, 1200.0, 0.5, 1e-2, 4096
ZOOM = (4000.0, 5500.0)  # a stretch with one of the wave's large shocks


def my_velocities(x, L, seed=5):
    """A long wave (three periods on the ring) with white noise on top: the noise
    makes small shocks at once, the wave gathers them into three large ones."""
    rng = np.random.default_rng(seed)
    return 0.5 * np.sin(2 * np.pi * 3 * x / L) + rng.uniform(-0.5, 0.5, x.size)


def compute():
    x = np.arange(N) + 0.5  # a lattice on the ring [0, N)
    v = my_velocities(x, N)
    gas = shockgas.particles.simulate(x, v, r=R, delta=DELTA, t_end=T, samples=10)
    field = shockgas.continuum.solve("hopf_lax", v, x=x, cells=CELLS, t_end=T)
    c = shockgas.compare.snapshot(gas.final.x, gas.final.v, gas.final.m, field, N=N, r=R, delta=DELTA)
    return gas, field, c


def draw_state(ax, gas, field, c, legend):
    ax.plot(gas.final.x, gas.final.v, ".", ms=2, color="tab:blue", label=f"particles (r = {R}, δ = {DELTA})")
    ax.plot(field.x, field.v, "-", color="black", lw=1, label="exact inviscid continuum (Hopf-Lax)")
    big = c.clusters.m >= c.min_mass
    ax.plot(c.clusters.x[big], c.clusters.v[big], "o", mfc="none", color="tab:red", ms=8,
            label=f"clusters of ≥ {c.min_mass:.0f} particles (centre of mass, velocity)")
    shocks = c.shocks.mass >= c.min_mass
    ax.plot(c.shocks.x[shocks], c.shocks.v[shocks], "kx", ms=6, label="shocks (position, velocity)")
    ax.set(xlabel="x [spacing]", ylabel="v [velocity]")
    if legend:
        ax.legend(fontsize=8, loc="center right")


def plot(gas, field, c, path):
    fig = plt.figure(figsize=(13, 8))
    whole = fig.add_subplot(2, 1, 1)
    zoom, masses = fig.add_subplot(2, 2, 3), fig.add_subplot(2, 2, 4)
    draw_state(whole, gas, field, c, legend=False)
    whole.axvspan(*ZOOM, color="0.9", zorder=0)
    whole.set(xlim=(0, N), title=f"t = {T:g}: matched mass fraction {c.match.matched_mass_fraction:.3f}; "
                                 f"ramps' slope × t = {c.sawtooth.median_slope_times_t:.3f} (theory 1)")
    draw_state(zoom, gas, field, c, legend=True)
    zoom.set(xlim=ZOOM, title="the grey stretch")
    pairs_m = c.clusters.m[c.match.cluster]
    shock_m = c.shocks.mass[c.match.shock]
    masses.loglog(shock_m, pairs_m, "o", ms=4, label="matched pairs")
    lim = [min(shock_m.min(), pairs_m.min()) / 1.5, max(shock_m.max(), pairs_m.max()) * 1.5]
    masses.plot(lim, lim, "k--", label="equal mass")
    masses.set(xlabel="shock mass [particle masses]", ylabel="cluster mass [particle masses]",
               title=f"{len(c.match.shock)} pairs, rms |Δx| = {c.match.rms_position_error:.2f} spacings")
    masses.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main(out_dir="."):
    gas, field, c = compute()
    path = pathlib.Path(out_dir) / "shocks_vs_clusters.png"
    plot(gas, field, c, path)
    print(f"{c.n_clusters} clusters, {c.n_shocks} shocks, {len(c.match.shock)} matched; "
          f"matched mass fraction {c.match.matched_mass_fraction:.3f}")
    print(f"wrote {path}")
    return {"figure": path, "matched_mass_fraction": c.match.matched_mass_fraction,
            "slope_times_t": c.sawtooth.median_slope_times_t}


if __name__ == "__main__":
    main(*sys.argv[1:])
