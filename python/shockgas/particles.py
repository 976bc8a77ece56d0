"""The particle gas on your own bodies: shockgas.particles.simulate, ensemble,
initial_bodies; and shockgas.hull, the exact sticky gas.

Units: lengths in the initial mean spacing, times in spacing / typical velocity,
masses in particle masses (velocities in length/time).
"""

from . import _shockgas
from ._progress import Progress
from ._records import Bodies, Clusters, ParticleRun
from .scenes import run

_core = _shockgas.particles


def simulate(x, v, m=None, *, progress=None, **keys):
    """Run the event-driven engine from the bodies x, v, m to t_end.

    x          positions [length], sorted; on a ring in [0, L)
    v          velocities [length/time]
    m          masses [mass] (> 0); None: every body of mass 1
    progress   None, True (a bar), or progress(stage, fraction, time)
    keys       the scene keys of [particles] (below), and L: the ring length
               [length] (the scene key initial.L; 0 or absent: N, one body per
               unit length; on a line the extent that sets the mean spacing)

    Returns a ParticleRun: the time series at log-spaced sample times (t, T,
    mean_v, n_bodies, n_clusters, collisions, ...), the final state, and what
    the keys ask for (snapshots, histogram, spacetime).

    The arrays are copied once (the engine owns and changes its state). A
    collision of neighbours approaching at g = v_left - v_right > 0 keeps their
    momentum and leaves them at -r g; below g = delta it is elastic, or a merge
    with subthreshold = "sticky"; r = 0 merges every collision (the sticky gas).
    Each key is checked as in a scene: a bad value raises shockgas.InputError (a
    ValueError) naming it, e.g. "particles.r = 2 is not allowed; allowed: a
    finite number in [0, 1]". RuntimeError: the run failed. KeyboardInterrupt:
    Ctrl-C, the engine stops within a few thousand collisions.

    Keys of [particles]:
    """
    with Progress(progress) as callback:
        return _run(_core._simulate(x, v, m, callback, **keys))


def ensemble(*, out=None, progress=None, **keys):
    """An ensemble of realizations of a scene's initial condition: the scene
    {"initial": ..., "particles": ..., "compare": ...} made of the keys, run by
    shockgas.run (its Result: /particles/T, /particles/T_stderr, ... and the
    figures, e.g. figures["analysis.T_exponent"]).

    keys   scene keys of [initial] (N, seed, velocities, ...; below), of
           [particles] (r, delta, t_end, realizations, threads, ...: see
           simulate) and of [compare] (fit_window, ...), each by its own name
    out    also write the run's directory there (as shockgas.run)

    Realization k uses the seed realization_seed(seed, k); the ensemble is
    bit-identical for any number of threads.

    Keys of [initial]:
    """
    scene = _shockgas._keywords_scene(["initial", "particles", "compare"], "shockgas.particles.ensemble", **keys)
    scene.setdefault("particles", {})
    return run(scene, out=out, plots=out is not None, progress=progress)


def initial_bodies(realization=0, **keys):
    """Realization k of a scene's initial condition as Bodies x, v, m (and the
    domain length L), from the scene keys of [initial] (as ensemble)."""
    return Bodies(_core._initial_bodies(realization, **keys))


def hull(x, v, m=None, t=0.0, *, geometry="ring", L=0.0):
    """The exact state at time t of the sticky gas (every collision a merge)
    from the bodies x, v, m: its clusters, sorted by x.

    x          positions [length] at t = 0, sorted (ring: in [0, L))
    v          velocities [length/time]
    m          masses [mass] (> 0); None: every body of mass 1
    t          time [time], >= 0
    geometry   "ring" (periodic, length L) or "line" (open)
    L          ring length [length]; 0: N (one body per unit length)

    Returns Clusters: x [length] (ring: in [0, L)), v [length/time], m [mass],
    first and count (the initial bodies each holds; on a ring the last may
    wrap past N - 1), and t.

    Exact: each cluster is an edge of the lower convex hull of the cumulative
    points (M_k, S_k), M_k = sum_{i<=k} m_i, S_k = sum_{i<=k} m_i (x_i + t v_i);
    its mass is the edge's run of M, its position the S-increment over the
    mass-increment, its velocity the mass-weighted mean (E, Rykov & Sinai 1996;
    Brenier & Grenier 1998). O(N); the engine at r = 0 gives the same partition.
    The arrays are read in place, not copied.

    >>> import numpy as np, shockgas
    >>> c = shockgas.hull(np.array([0.5, 1.5]), np.array([1.0, -1.0]), t=1.0)
    >>> c.m, c.x, c.v
    (array([2.]), array([1.]), array([0.]))
    """
    return Clusters(_shockgas._hull(x, v, m, t, geometry=geometry, L=L))


def _run(fields):
    fields["final"] = Bodies(fields["final"])
    fields["snapshots"] = [Bodies(s) for s in fields["snapshots"]]
    return ParticleRun(fields)


simulate.__doc__ = simulate.__doc__.rstrip(" ") + _core._keywords
ensemble.__doc__ = ensemble.__doc__.rstrip(" ") + _core._initial_keywords
