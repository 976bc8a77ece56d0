"""shockgas: the one-dimensional inelastic / sticky particle gas and the inviscid
Burgers equation side by side, from Python.

    import shockgas
    r = shockgas.run("data/scenes/default.toml")           # a scene, outputs in memory
    r = shockgas.run({"initial": {"N": 1000}, "particles": {"r": 0.5}})
    r.datasets["/particles/T"], r.figures["analysis.T_exponent"]

    run = shockgas.particles.simulate(x, v, r=0.5, delta=1e-2, t_end=1e3)
    clusters = shockgas.hull(x, v, m, t)                   # the exact sticky gas
    field = shockgas.continuum.solve("godunov", v0, dx=1/256, t_end=0.3)
    shocks = shockgas.compare.detect_shocks(field.v, field.length, field.rho)
    s = shockgas.statistics(["out/a", "out/b"])           # shock statistics over runs

Units: lengths in the initial mean spacing, times in spacing / typical
velocity, masses in particle masses. Keyword options are the scene keys
(scene_keys(); docs/scenes.md), checked as a scene checks them: a bad one
raises InputError (a ValueError) naming the key. Long calls release the GIL,
show progress (progress=True, or a callable) and stop on Ctrl-C
(KeyboardInterrupt); calls from several threads are safe.
"""

from . import compare, continuum, particles
from ._shockgas import InputError, __version__, git_commit
from .particles import hull
from .scenes import Result, SolverNote, load, output_layout, run, run_toml, scene_keys
from .statistics import statistics

__all__ = [
    "InputError",
    "Result",
    "SolverNote",
    "compare",
    "continuum",
    "git_commit",
    "hull",
    "load",
    "output_layout",
    "particles",
    "run",
    "run_toml",
    "scene_keys",
    "statistics",
]
