"""Convergence of two finite-volume schemes to the exact inviscid solution.

Burgers' equation with continuity from v0 = 0.5 + sin(2 pi x), rho0 = 1 on the
periodic unit interval, by first-order Godunov and second-order MUSCL-Hancock
(godunov2), against the exact solution by the Legendre transform (Hopf-Lax) on
the same cells. Before the shock forms at t* = 1/(2 pi) the solution is smooth
and the L1 errors fall as dx and dx^2; after it, both schemes converge at first
order, because the shock is smeared over a few cells: its error is C dx, with C
depending on where the shock sits inside its cell. At t = 0.5 it sits at
x = 0.75, on a cell edge of every grid here, so the orders come out clean; at
other times C jumps from grid to grid (by up to a hundred times for godunov2).

    PYTHONPATH=build/python /usr/bin/python3 examples/continuum_convergence.py [OUT_DIR]

writes OUT_DIR/continuum_convergence.png (default: the current directory).
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import shockgas  # noqa: E402

V0 = "0.5 + sin(2*pi*x)"  # an expression in x, as the scene key initial.v0
SCHEMES = {"godunov": "tab:blue", "godunov2": "tab:orange"}
CELLS = [32, 64, 128, 256, 512, 1024, 2048]
TIMES = {"smooth, t = 0.1": 0.1, "after the shock, t = 0.5": 0.5}


def l1_errors(t):
    """L1 distance, sum |v - v_exact| dx, of each scheme on each grid."""
    errors = {name: [] for name in SCHEMES}
    for cells in CELLS:
        exact = shockgas.continuum.solve("hopf_lax", V0, cells=cells, t_end=t)
        for name in SCHEMES:
            f = shockgas.continuum.solve(name, V0, cells=cells, t_end=t)
            errors[name].append(np.sum(np.abs(f.v - exact.v)) / cells)
    return {name: np.array(e) for name, e in errors.items()}


def order(errors):
    """The measured order: the least-squares slope of log error against log dx over the grids."""
    return np.polyfit(np.log(1.0 / np.array(CELLS)), np.log(errors), 1)[0]


def plot(results, path):
    fig, axes = plt.subplots(1, len(TIMES), figsize=(11, 4.5), sharey=True)
    dx = 1.0 / np.array(CELLS)
    for ax, (title, errors) in zip(axes, results.items()):
        for name, e in errors.items():
            ax.loglog(dx, e, "o-", color=SCHEMES[name], label=f"{name}: measured order {order(e):.2f}")
        for p, style in ((1, ":"), (2, "-.")):  # reference slopes through the finest first-order error
            e0 = errors["godunov"][-1]
            ax.loglog(dx, e0 * (dx / dx[-1]) ** p, "k" + style, lw=1, label=f"order {p} (slope reference)")
        ax.set(xlabel="cell width dx [length]", title=title)
        ax.legend(fontsize=8)
    axes[0].set_ylabel("L1 error of v against the exact solution [length²/time]")
    fig.suptitle("v0 = 0.5 + sin 2πx: finite volumes against the exact Hopf-Lax solution")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(out_dir="."):
    results = {title: l1_errors(t) for title, t in TIMES.items()}
    path = pathlib.Path(out_dir) / "continuum_convergence.png"
    plot(results, path)
    orders = {(title, name): order(e) for title, errors in results.items() for name, e in errors.items()}
    for (title, name), p in orders.items():
        print(f"{title}: {name} converges at order {p:.2f}")
    print(f"wrote {path}")
    return {"figure": path, "orders": orders}


if __name__ == "__main__":
    main(*sys.argv[1:])
