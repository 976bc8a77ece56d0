"""The cooling law of the inelastic gas, with error bars from an ensemble sweep over r.

For each restitution r an ensemble of independent realizations (N particles on a
ring, velocities uniform on [-1, 1], threshold delta = 1e-2) is run to t_end; the
temperature T(t) = <v^2> - <v>^2 is averaged over the realizations, with its
standard error. After t_stick = eps^(-3/2), eps = (1 - r)/2, every r cools as the
sticky gas, T ~ t^(-2/3) (Ben-Naim, Chen, Doolen & Redner, PRL 83, 4069, 1999,
eq. 3: fitted exponents 0.67, 0.67, 0.66 for r = 0, 0.5, 0.9).

    PYTHONPATH=build/python /usr/bin/python3 examples/cooling_sweep.py [OUT_DIR]

writes OUT_DIR/cooling_sweep.png (default: the current directory).
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import shockgas  # noqa: E402

RESTITUTIONS = (0.0, 0.5, 0.9)
N, REALIZATIONS, T_END = 20000, 8, 2000.0


def sweep():
    """One ensemble per r: its Result (datasets and figures named as in docs/output.md)."""
    return {r: shockgas.particles.ensemble(N=N, seed=2024, r=r, delta=1e-2, t_end=T_END, samples=30,
                                           realizations=REALIZATIONS, clusters=False, fit_window=10.0)
            for r in RESTITUTIONS}


def jackknife_error(result):
    """The exponent's error from the realizations (the least-squares error of a fit
    through correlated sample times is several times too small), or None."""
    return result.figures.get("analysis.T_exponent_jackknife_error")


def plot(results, path):
    fig, (ax, ax_exp) = plt.subplots(1, 2, figsize=(11, 4.5), gridspec_kw={"width_ratios": [1.6, 1]})
    # Fits that coincide (r = 0 and 0.5 cool alike) stay visible: wide solid
    # under narrower dashed and dotted lines.
    styles = (("tab:blue", "-", 4.0), ("tab:orange", (0, (6, 3)), 2.2), ("tab:green", (0, (1, 1.5)), 2.0))
    for (r, res), (colour, style, width) in zip(results.items(), styles):
        d = res.datasets
        ax.errorbar(d["/particles/t"], d["/particles/T"], yerr=d["/particles/T_stderr"], fmt="o", ms=3,
                    capsize=2, color=colour, label=f"r = {r}: ensemble mean ± standard error")
        t_fit, T_fit = d["/particles/analysis/T_fit_t"], d["/particles/analysis/T_fit_T"]
        ax.plot(t_fit, T_fit, ls=style, color=colour, lw=width,
                label=f"r = {r}: fit T ~ t^({res.figures['analysis.T_exponent']:.3f})")
    # The theory's slope -2/3, anchored on the r = 0 fit at its window's start.
    t0, T0 = results[0.0].datasets["/particles/analysis/T_fit_t"][0], results[0.0].datasets[
        "/particles/analysis/T_fit_T"][0]
    t = np.geomspace(t0 / 10, T_END, 50)
    ax.plot(t, T0 * (t / t0) ** (-2 / 3), "k--", label="theory: T ~ t^(-2/3) (sticky gas)")
    ax.set(xscale="log", yscale="log", xlabel="t [spacing / velocity]",
           ylabel="T = <v²> - <v>² [velocity²]",
           title=f"cooling, N = {N}, δ = 0.01, {REALIZATIONS} realizations")
    ax.legend(fontsize=8)
    exponents = [results[r].figures["analysis.T_exponent"] for r in RESTITUTIONS]
    errors = [jackknife_error(results[r]) for r in RESTITUTIONS]
    ax_exp.errorbar(RESTITUTIONS, exponents, yerr=[np.nan if e is None else e for e in errors], fmt="o", capsize=3,
                    label="fitted (± jackknife error over the realizations)")
    ax_exp.plot(RESTITUTIONS, [-0.67, -0.67, -0.66], "s", mfc="none", color="tab:red",
                label="paper (N = 10⁶)")
    ax_exp.axhline(-2 / 3, color="k", ls="--", label="theory -2/3")
    ax_exp.set(xlabel="restitution r [1]", ylabel="exponent of T(t) [1]", title="late-time exponent",
               xlim=(-0.1, 1.0))
    ax_exp.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(out_dir="."):
    results = sweep()
    path = pathlib.Path(out_dir) / "cooling_sweep.png"
    plot(results, path)
    exponents = {r: results[r].figures["analysis.T_exponent"] for r in RESTITUTIONS}
    for r, e in exponents.items():
        error = jackknife_error(results[r])
        spread = f"± {error:.3f} (jackknife over {REALIZATIONS} realizations)" if error is not None else \
            "(no error estimate from one realization)"
        print(f"r = {r}: T ~ t^({e:.3f} {spread})")
    print(f"wrote {path}")
    return {"figure": path, "exponents": exponents}


if __name__ == "__main__":
    main(*sys.argv[1:])
