"""The continuum solvers on your own data: shockgas.continuum.solve, solvers.

Burgers' equation with continuity, v_t + v v_x = nu v_xx, rho_t + (rho v)_x = 0,
on the periodic domain [0, length) (or with outflow boundaries), by every
registered solver (shockgas.continuum.solvers()). Units: lengths [length],
times [time], velocities [length/time], densities [mass/length].
"""

from . import _shockgas
from ._progress import Progress
from ._records import Field, Shocks

_core = _shockgas.continuum


def solve(name, v0, rho0=None, dx=None, t_end=1.0, *, x=None, m=None, progress=None, **keys):
    """Solve from the initial data to t_end with the registered solver `name`.

    name     a registered solver (shockgas.continuum.solvers(); the scene key
             continuum.solvers names them the same)
    v0, rho0 the initial velocity [length/time] and density [mass/length], one of:
             * arrays of cell values on len(v0) equal cells of width dx [length]
               (rho0 None: 1): the data are constant on each cell. The solution
               is on the same cells, or on a multiple of them (cells=...); the
               exact solver is exact for such data.
             * expressions in x (strings, muParser syntax, as the scene keys
               initial.v0, initial.rho0) on [0, domain) (domain: a keyword, as
               initial.domain, default 1), solved on `cells` cells.
             * with x: point masses at x [length] (sorted, in [0, L)) with
               velocities v0 and masses m (None: 1) on the ring of length L (a
               keyword, as initial.L; 0: N), as a scene's particles feed the
               continuum (deposited on the cells).
    t_end    the time of the solution [time] (the scene key continuum.t_end)
    progress None, True (a bar), or progress(stage, fraction, time)
    keys     the scene keys of [continuum] (below): cells, nu, cfl, rtol, ...

    Returns a Field: x (cell centres), v, rho, shocks (for solvers that know
    them), t, method, stats, wall_seconds.

    An argument that the form of v0 does not use (dx or L with expressions,
    domain or L with cell values, m without x, rho0 or dx or domain with x) is
    refused, not ignored. Each key is checked as in a scene, and the solver's
    own limits (its CFL bound, cells against nu, ...) before any work:
    shockgas.InputError (a ValueError) naming the key. RuntimeError: the solver
    failed. KeyboardInterrupt: Ctrl-C, the solver stops at its next progress
    point.

    Keys of [continuum]:
    """
    with Progress(progress) as callback:
        fields = _core._solve(name, v0, rho0, dx, x, m, callback, t_end=t_end, **keys)
    return field(fields)


def solvers():
    """Every registered solver: a list of dicts with name, summary, label,
    colour, and whether it gives a density, knows its shocks, is viscous (uses
    nu), is the exact inviscid solution, runs by default."""
    return _core._solvers()


def field(fields):
    """A Field from its dict of fields (as solve returns it)."""
    fields = dict(fields)
    if fields.get("shocks") is not None and not isinstance(fields["shocks"], Shocks):
        fields["shocks"] = Shocks(fields["shocks"])
    return Field(fields)


solve.__doc__ = solve.__doc__.rstrip(" ") + _core._keywords
