"""Shocks against clusters on your own data: shockgas.compare.

The particle side: clusters of a state (find_clusters), the particles on a grid
(deposit). The continuum side: shocks of a field (detect_shocks), the sawtooth
ramps between them (sawtooth). Both: match, and snapshot, which is all of it at
one time as a scene's [compare] does. Units: lengths [length], times [time],
velocities [length/time], masses [mass].
"""

from . import _shockgas
from ._records import Clusters, Record, Shocks

_core = _shockgas.compare


def detect_shocks(v, length, rho=None, *, min_jump=0.0, max_width_cells=8):
    """Shocks of cell averages v (and rho) on len(v) equal cells of the periodic
    domain [0, length).

    A run of compressive interfaces (v_{i+1} < v_i) is one shock: the ramps on
    either side are extrapolated into it, the position is where a step between
    them conserves the integral of v, the jump J = v_R - v_L, the mass the excess
    of rho over the ramps' background, the velocity the Rankine-Hugoniot speed
    (v_L + v_R) / 2. Exact for a sawtooth with ramps of equal slope. A run whose
    own drop is less than min_jump / 2 is a kink between ramps, not a shock.

    min_jump         smallest |J| counted [length/time]; 0: 5% of max v - min v
    max_width_cells  widest compression region taken as one shock [cells]

    Returns Shocks (x, mass, jump, v), sorted by x.
    """
    return Shocks(_core._detect_shocks(v, rho, length, min_jump, max_width_cells))


def find_clusters(x, v, m=None, *, L, t, **keys):
    """The clusters of a particle state at time t on the ring of length L: maximal
    runs of neighbours closer than max_gap and co-moving within max_dv (a run may
    wrap across x = 0); each at its centre of mass, with its momentum / mass.

    keys   r, delta (the gas: particles.r, particles.delta; r = 0: each merged
           body is its own cluster) and the [compare] keys cluster_gap,
           cluster_dv (0: the criteria derived from delta, the mean spacing L/N
           and t, as a scene's comparison uses)

    Returns Clusters (x, v, m, first, count), in order of their first body.
    """
    return Clusters(_core._find_clusters(x, v, m, L, t, **keys))


def match(shocks, clusters, L, *, max_distance=0.0, min_mass=0.0):
    """Shocks matched one-to-one to clusters on the ring of length L.

    Pairs closer than max_distance [length] (0: a quarter of the mean spacing
    of the shocks) are accepted greedily by increasing distance; shocks and
    clusters lighter than min_mass [mass] take no part.

    Returns a Record: shock, cluster (indices of each pair), position_error
    (x_cluster - x_shock, periodic), mass_error, velocity_error,
    unmatched_shocks, unmatched_clusters, matched_mass_fraction (matched
    cluster mass / eligible cluster mass; 1 when every cluster has its shock),
    max_position_error, rms_position_error, max_distance used, ...
    """
    return Record(_core._match(shocks, clusters, L, max_distance, min_mass))


def deposit(x, v, m=None, *, length, cells, scheme="cic"):
    """Point masses on len = cells equal cells of the ring [0, length): "cic"
    (cloud in cell) or "ngp" (nearest cell); a position outside [0, length) is
    taken modulo length. Returns a Record: x (centres), rho = mass/dx,
    v = momentum/mass (empty cells interpolated between occupied ones), mass
    (0 marks an empty cell), momentum."""
    return Record(_core._deposit(x, v, m, length, cells, scheme))


def sawtooth(v, length, t, shock_x, *, weights=None, skip_cells=2, min_cells=3):
    """Slopes of the ramps of v between consecutive shocks at shock_x on the
    periodic domain [0, length) at time t (theory: 1/t, slope * t = 1), each a
    weighted least-squares line over the cells at least skip_cells + 1/2 cells
    from its shocks. Returns a Record: x_begin, x_end, cells, slope [1/time],
    slope_error, slope_times_t [1], and median_slope_times_t."""
    return Record(_core._sawtooth(v, length, t, shock_x, weights, skip_cells, min_cells))


def snapshot(x, v, m, field, *, N, **keys):
    """A particle state and a continuum Field at the same time, compared as a
    scene's [compare] does: clusters, shocks, the particles on the field's
    grid, the matching and the sawtooth fits.

    x, v, m  the particle state at field.t (m None: 1)
    field    a Field (shockgas.continuum.solve) on the ring [0, field.length)
    N        the number of initial particles (sets the mean particle mass)
    keys     r, delta of the gas, and the [compare] keys (below)

    Returns a Record: t, min_mass, particle_fields, clusters, shocks, match,
    sawtooth, particle_sawtooth, n_shocks, n_clusters, shock_count_ratio.

    Keys of [compare]:
    """
    d = _core._snapshot(x, v, m, field, N, **keys)
    for name in ("particle_fields", "match", "sawtooth", "particle_sawtooth"):
        d[name] = Record(d[name])
    d["clusters"] = Clusters(d["clusters"])
    d["shocks"] = Shocks(d["shocks"])
    return Record(d)


snapshot.__doc__ = snapshot.__doc__.rstrip(" ") + _core._keywords
