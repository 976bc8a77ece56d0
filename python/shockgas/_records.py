"""Result objects: named numpy arrays and numbers, with a readable repr."""

import numpy as np


def _describe(value):
    if isinstance(value, np.ndarray):
        return f"array{value.shape} {value.dtype}"
    if isinstance(value, Record):
        return type(value).__name__
    if isinstance(value, list):
        return f"list of {len(value)}"
    if isinstance(value, dict):
        return f"dict of {len(value)}"
    return repr(value)


class Record:
    """Fields as attributes (``run.T``) and as items (``run["T"]``).

    The arrays are numpy arrays that own their data; nothing is copied when
    they are read.
    """

    def __init__(self, fields):
        self.__dict__.update(fields)

    def __getitem__(self, name):
        return self.__dict__[name]

    def __contains__(self, name):
        return name in self.__dict__

    def keys(self):
        return self.__dict__.keys()

    def to_dict(self):
        """The fields as a plain dict (the same objects)."""
        return dict(self.__dict__)

    def __repr__(self):
        lines = [f"  {name}: {_describe(value)}" for name, value in self.__dict__.items()]
        return f"{type(self).__name__}(\n" + "\n".join(lines) + "\n)"


class Bodies(Record):
    """Point masses: x [length] (sorted; ring: in [0, L)), v [length/time], m [mass]."""


class Clusters(Record):
    """Clusters sorted by x: x [length], v [length/time], m [mass], and the
    initial bodies each holds, first (index of the first; on a ring a cluster may
    wrap past N - 1) and count."""


class Shocks(Record):
    """Shocks sorted by x: x [length], mass [mass], jump = v_right - v_left
    [length/time] (< 0), v [length/time]."""


class ParticleRun(Record):
    """One run of the particle engine (shockgas.particles.simulate).

    Time series at the log-spaced sample times (one entry per sample reached):
      t [time], T [length^2/time^2] (mass-weighted <v^2> - <v>^2), mean_v
      [length/time], n_bodies, n_clusters (the clusters of at least
      min_cluster_particles particles, 2 by default: default criteria at the
      sample's time; with 2 a lone body only when heavier than 1.5 M / N, with
      k > 2 the clusters heavier than (k - 1/2) M / N), collisions, inelastic,
      elastic, merges [1],
      dissipated [mass length^2/time^2].
    final: Bodies at stop.time. snapshots: list of Bodies with their time t.
    histogram: z [length/time^(2/3)], t [time], density (rows: times) of
      z = (v - <v>) t^(1/3), or None. spacetime: label [1] (the
      recorded particles, at most spacetime_particles of them evenly spaced,
      the first and the last always), t [time], x [length] (rows: frames,
      columns: the labels), or None.
    stop: reason ("completed", "collapse", "event_limit", "wall_limit",
      "rounding_stall"), time [time], position [length].
    total_collisions [1], wall_seconds [s].
    """


class Field(Record):
    """A continuum solution at time t (shockgas.continuum.solve).

    solver, t [time], length [length]; x: cell centres [length]; v: cell
    averages of the velocity [length/time]; rho: of the density [mass/length]
    (None for solvers without one); shocks: Shocks, or None for solvers that do
    not know theirs (shockgas.compare.detect_shocks finds them); method: which
    path ran and why; stats: the solver's counters; wall_seconds [s].
    """
