#!/usr/bin/python3
"""The exact velocity laws of white-noise Burgers turbulence over shockgas's data.

Runs `shockgas run` on a scene written here (10 realizations of N = 10^6 lattice
particles, velocities uniform on [-1, 1] (D = 1/3), r = 0, to t = 1000, and the exact
hopf_lax field of realization 0 on 1618034 cells) and draws, in z = (v - <v>) t^(1/3):

  left   the Eulerian velocity: histogram of the hopf_lax field's cell values against
         (4D)^(1/3) Z, Z Chernoff's variable (eulerian_velocity_law.hpp);
  right  the mass-weighted cluster velocity (particles/histogram of the r = 0 gas)
         against the exact cluster law (cluster_velocity_law.hpp), with the Eulerian
         law dashed for comparison;
  below  the same on a logarithmic scale.

The laws come from scripts/reference/exact_laws.py (SciPy), an implementation independent of the
C++ one (they agree to ~1e-10, tests/compare/data/cluster_mass_reference.csv).

    /usr/bin/python3 scripts/reference/plot_exact_laws.py [BUILD_DIR] [OUT_PNG]
    (defaults: build, docs/img/paper/exact-laws.png; about 10 s of runs plus 10 s of laws)
"""
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import exact_laws  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plots"))
from shockplot.run_files import RESULT, open_result  # noqa: E402
from shockplot.saving import save  # noqa: E402

D = 1.0 / 3.0  # sigma^2 l for velocities uniform on [-1, 1] at unit spacing
T_END = 1000.0
SCENE = """# written by scripts/reference/plot_exact_laws.py
[scene]
description = "white noise, r = 0, t = 1000: the exact velocity laws over the data"
expected_runtime = "about 10 s"
[initial]
N = 1000000
velocities = "uniform"
seed = 7
[particles]
r = 0
t_end = %g
samples = 4
realizations = 10
histogram_bins = 60
histogram_zmax = 2.4
clusters = false
[continuum]
solvers = ["hopf_lax"]
cells = 1618034
t_end = %g
""" % (T_END, T_END)


def run(build, workdir):
    scene = os.path.join(workdir, "exact-laws.toml")
    with open(scene, "w") as f:
        f.write(SCENE)
    out = os.path.join(workdir, "out")
    subprocess.run([os.path.join(build, "shockgas"), "run", scene, "--out", out, "-q", "--no-plots"], check=True)
    return out


def eulerian_histogram(f, edges):
    v = np.asarray(f["continuum/hopf_lax/v"])
    z = (v - v.mean()) * T_END ** (1.0 / 3.0)
    counts, _ = np.histogram(z, bins=edges)
    return counts / (len(z) * np.diff(edges))


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    out_png = sys.argv[2] if len(sys.argv) > 2 else os.path.join("docs", "img", "paper", "exact-laws.png")
    with tempfile.TemporaryDirectory() as workdir, open_result(run(build, workdir)) as f:
        hist = f["particles/histogram"]
        z_mass = np.asarray(hist["z"])
        row = int(np.argmin(np.abs(np.asarray(hist["t"]) - T_END)))
        p_mass = np.asarray(hist["density"])[row]
        width = z_mass[1] - z_mass[0]
        edges = np.append(z_mass - width / 2, z_mass[-1] + width / 2)
        p_euler = eulerian_histogram(f, edges)
    zz = np.linspace(-2.4, 2.4, 241)
    law_euler = exact_laws.eulerian_density(zz, D)
    law_mass = exact_laws.cluster_density(zz, D)

    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5), sharex=True)
    for col, (data, label, law, law_label) in enumerate([
            (p_euler, "hopf_lax field (one realization), all cells", law_euler, "exact: $(4D)^{1/3} Z$ (Chernoff)"),
            (p_mass, "r = 0 gas (10 realizations), mass weighted", law_mass, "exact: cluster law")]):
        for row_ax, log in ((0, False), (1, True)):
            ax = axes[row_ax, col]
            ax.step(z_mass, data, where="mid", color="C0", label=label + ", t = 1000")
            ax.plot(zz, law, color="k", lw=1.2, label=law_label)
            if col == 1:
                ax.plot(zz, law_euler, color="0.5", lw=1, ls="--", label="Eulerian law")
            if log:
                ax.set_yscale("log")
                ax.set_ylim(1e-6, 3)
                ax.set_xlabel(r"$z = (v - \langle v\rangle)\, t^{1/3}$")
            ax.set_ylabel(r"density of $z$")
            ax.grid(alpha=0.3)
        axes[1, col].legend(fontsize=8, loc="lower center")
    axes[0, 0].set_title("Eulerian velocity (volume weighted)")
    axes[0, 1].set_title("cluster velocity (mass weighted)")
    fig.suptitle(r"white noise, $D = \sigma^2 \ell = 1/3$, $N = 10^6$, $t = 1000$: the exact laws have no free parameter")
    fig.tight_layout()
    os.makedirs(os.path.dirname(out_png) or ".", exist_ok=True)
    save(fig, out_png, f"{RESULT} of the scene above, scripts/reference/exact_laws.py", tight=False)
    print(out_png)


if __name__ == "__main__":
    main()
