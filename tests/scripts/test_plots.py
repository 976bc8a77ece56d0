"""The pictures of plots/plot_result.py (plots/shockplot/), built from the
result files of small runs and inspected artist by artist: one legend that is
right on every panel, the particles drawn only where they are data, a unit on
every axis, the exact solution black and dashed and named "exact", guides whose
amplitude is fitted over their window, the initial condition and the local
exponent shown. The command is $SHOCKGAS (CTest sets it)."""
import os
import subprocess
import sys

import matplotlib
import numpy as np
import pytest
from matplotlib.colors import to_rgba

matplotlib.use("Agg")
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
PLOTS = os.path.join(ROOT, "plots")
sys.path.insert(0, PLOTS)
from shockplot.pictures import figures as figures_from  # noqa: E402
from shockplot.run_files import open_result, read_summary  # noqa: E402
from shockplot.spacetime import shown_lines  # noqa: E402

# White noise on a lattice (the exact laws apply), particles, three solvers of
# which hopf_cole gives no density, and the comparison.
GAS = """[initial]
N = 600
seed = 2
[particles]
r = 0.5
delta = 1e-2
t_end = 300
samples = 16
realizations = 2
histogram_bins = 24
spacetime = true
spacetime_frames = 20
[continuum]
solvers = ["godunov", "hopf_cole", "hopf_lax"]
cells = 600
nu = 0.5
[compare]
solver = "hopf_lax"
fit_window = 10
"""

# A smooth start: hopf_cole (no density) listed before hopf_lax, the order in
# which the old plots drew hopf_lax's density in hopf_cole's colour; the sticky
# gas by its exact hull, without a comparison.
SINE = """[initial]
N = 1000
velocities = "expression"
v0 = "0.5 + sin(2*pi*x)"
rho0 = "1"
domain = 1.0
[particles]
r = 0
solver = "hull"
t_end = 0.5
samples = 5
[continuum]
solvers = ["godunov", "hopf_cole", "pressureless", "hopf_lax"]
cells = 128
t_end = 0.5
nu = 0.02
[output]
animation = true
animation_frames = 21
"""

# Random positions (no exact law: guides instead) and r = 0.95, whose
# homogeneous-cooling window [1/eps, eps^(-3/2)] = [40, 253] holds samples.
COOLING = """[initial]
N = 400
positions = "random"
seed = 4
[particles]
r = 0.95
delta = 1e-2
t_end = 3000
samples = 36
[compare]
fit_window = 10
"""

# A few bodies: the gas's laws, statistical, are not drawn over them.
FEW = """[initial]
N = 12
seed = 3
[particles]
r = 0.5
t_end = 50
samples = 10
[compare]
fit_window = 10
"""

# A shock from the start: its amplitude stays (max v - min v) / 2 = 0.75, to rounding.
STEP = """[initial]
velocities = "expression"
v0 = "(x < 0.5) ? 1 : -0.5"
rho0 = "1"
domain = 1.0
[continuum]
solvers = ["hopf_lax"]
cells = 100
t_end = 0.2
[output]
animation = true
animation_frames = 11
"""

SWEEP = """[initial]
N = 300
[particles]
t_end = 100
samples = 10
histogram_bins = 16
[sweep]
variants = ["particles.r=0", "particles.r=0.5"]
"""


def run(tmp, name, scene):
    path = tmp / f"{name}.toml"
    path.write_text(scene + ("" if "[output]" in scene else "[output]\n") + "plots = false\n")
    out = tmp / name
    command = os.environ.get("SHOCKGAS", os.path.join(ROOT, "build", "shockgas"))
    subprocess.run([command, "run", str(path), "--out", str(out), "-q"], check=True, stdout=subprocess.DEVNULL)
    return out


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("plots")
    return {name: run(tmp, name, scene) for name, scene in
            [("gas", GAS), ("sine", SINE), ("cooling", COOLING), ("sweep", SWEEP), ("few", FEW), ("step", STEP)]}


def figures_of(out):
    with open_result(out) as f:
        return figures_from(f, read_summary(out))


@pytest.fixture(scope="module")
def figures(runs):
    return {name: figures_of(out) for name, out in runs.items()}


def panels(fig):
    """The axes that show data (not hidden, not turned off to hold a note)."""
    return [ax for ax in fig.axes if ax.get_visible() and ax.axison]


def labelled(ax):
    """(label, colour) of every artist a legend would list, on one panel."""
    handles, texts = ax.get_legend_handles_labels()
    return [(text, colour_of(handle)) for handle, text in zip(handles, texts)]


def colour_of(artist):
    if hasattr(artist, "get_color"):
        return to_rgba(artist.get_color())
    if hasattr(artist, "lines"):  # an errorbar container
        return to_rgba(artist.lines[0].get_color())
    return to_rgba(artist.get_edgecolor())


def the_legend(fig):
    assert len(fig.legends) == 1, "one legend per figure"
    legend = fig.legends[0]
    handles = getattr(legend, "legend_handles", None) or legend.legendHandles  # matplotlib >= 3.7 / older
    return {text.get_text(): colour_of(handle) for text, handle in zip(legend.get_texts(), handles)}


# Finding 10: one legend, right on every panel.
@pytest.mark.parametrize("run", ["sine", "gas"])
def test_one_legend_is_right_on_every_panel(figures, run):
    fig = figures[run]["fields.png"]
    legend = the_legend(fig)
    for ax in panels(fig):
        assert ax.get_legend() is None, "no panel has a legend of its own"
        for text, colour in labelled(ax):
            assert text in legend, f"{text} is drawn but not explained"
            assert legend[text] == colour, f"{text}: the legend's colour is not the panel's"


@pytest.mark.parametrize("run", ["sine", "gas"])
def test_a_solver_without_density_is_absent_from_the_density_panel(figures, run):
    fig = figures[run]["fields.png"]
    velocity, density = [ax for ax in panels(fig) if "velocity" in ax.get_ylabel() or "density" in ax.get_ylabel()]
    in_velocity = {text for text, _ in labelled(velocity)}
    in_density = {text for text, _ in labelled(density)}
    cole = [t for t in in_velocity if t.startswith("hopf_cole")]
    assert cole and not any(t.startswith("hopf_cole") for t in in_density)
    assert any(t.startswith("godunov") for t in in_density) and "exact (hopf_lax)" in in_density


def test_shock_and_cluster_markers_are_explained(figures):
    legend = the_legend(figures["gas"]["fields.png"])
    assert any(t.startswith("clusters of the gas") for t in legend)
    assert any(t.startswith("shocks of hopf_lax") for t in legend)


# Finding 11: the particles are drawn where they deposited mass, never in the
# cells whose velocity was interpolated.
def test_interpolated_cells_are_not_drawn_as_data(runs, figures):
    with open_result(runs["gas"]) as f:
        x, occupied = f["compare/x"][:], f["compare/occupied"][:] > 0
        description = f["compare/v_particles"].attrs["description"]
        assert "interpolated" in (description.decode() if isinstance(description, bytes) else description)
    assert (~occupied).any(), "the run must have empty cells for the test to mean anything"
    fig = figures["gas"]["fields.png"]
    drawn = [line for ax in panels(fig) for line in ax.get_lines() if line.get_label().startswith("particles")]
    assert len(drawn) == 2  # velocity and density
    for line in drawn:
        xs = np.asarray(line.get_xdata())
        assert len(xs) == occupied.sum()
        assert np.isin(xs, x[occupied]).all() and not np.isin(xs, x[~occupied]).any()


# Finding 13: units, the exact solution, the guides, the Phi axis.
def test_every_axis_carries_a_unit(figures):
    for run, drawn in figures.items():
        for name, fig in drawn.items():
            for ax in panels(fig):
                for text in (ax.get_xlabel(), ax.get_ylabel()):
                    if text or ax is fig.axes[-1]:
                        assert text.endswith("]") and " [" in text, f"{run}/{name}: '{text}' has no unit"
                assert ax.get_ylabel(), f"{run}/{name}: a panel without a y label"


def test_the_exact_solution_is_black_dashed_and_named_exact(figures):
    checked = 0
    for run, drawn in figures.items():
        for name, fig in drawn.items():
            for ax in panels(fig):
                for artist in ax.get_lines() + [p for p in ax.patches]:
                    if artist.get_label().startswith("exact"):
                        colour = artist.get_color() if hasattr(artist, "get_color") else artist.get_edgecolor()
                        assert to_rgba(colour)[:3] == (0, 0, 0), f"{run}/{name}: {artist.get_label()}"
                        if artist.get_linestyle() == "None":  # one exact number at one time: a black marker
                            assert artist.get_marker() not in (None, "None", ""), f"{run}/{name}: {artist.get_label()}"
                            assert to_rgba(artist.get_markeredgecolor())[:3] == (0, 0, 0), f"{run}/{name}"
                        else:
                            assert artist.get_linestyle() in ("--", "dashed"), f"{run}/{name}: {artist.get_label()}"
                        checked += 1
    legend = the_legend(figures["gas"]["fields.png"])
    assert "exact (hopf_lax)" in legend
    for picture in ("temperature.png", "velocity_distribution.png", "clusters.png"):
        assert any(t.startswith("exact") for t in the_legend(figures["gas"][picture])), picture
    assert checked >= 6


def test_guides_are_fitted_on_their_window_not_anchored_on_a_point(runs, figures):
    with open_result(runs["cooling"]) as f:
        t, T = f["particles/t"][:], f["particles/T"][:]
    fig = figures["cooling"]["temperature.png"]
    guides = [line for ax in panels(fig) for line in ax.get_lines() if hasattr(line, "fit_window")]
    # 400 particles at r = 0.95: the sticky law would hold from 10 t_stick = 2530,
    # past N^(3/2) / 10 = 800 (about 4 clusters left at t = 3000): only the
    # homogeneous-cooling guide is drawn (theory.sticky_cooling does not hold).
    assert {round(g.fit_power, 6) for g in guides} == {-2.0}
    for guide in guides:
        (t0, t1), power = guide.fit_window, guide.fit_power
        inside = (t >= t0) & (t <= t1)
        assert inside.sum() >= 2
        amplitude = guide.get_ydata()[0] / guide.get_xdata()[0] ** power
        residual = np.log(T[inside]) - np.log(amplitude * t[inside] ** power)
        assert abs(residual.mean()) < 1e-9, "least squares in ln: the residuals average to zero"
        assert np.abs(residual).max() > 1e-6, "the data are not on a power law: a point anchor would show here"


def test_the_phi_axis_names_what_is_plotted(figures):
    for run in ("gas", "sweep"):
        ax = figures[run]["velocity_distribution.png"].axes[0]
        assert r"(v - \langle v\rangle)\,t^{1/3}" in ax.get_xlabel()


# The pictures the issue asked for.
def test_the_initial_condition_is_shown(figures):
    assert "initial condition (t = 0)" in the_legend(figures["sine"]["fields.png"])
    titles = [ax.get_title() for ax in panels(figures["gas"]["fields.png"])]
    assert any(t.startswith("initial condition") for t in titles)


def test_the_local_exponent_is_drawn_against_the_theory_levels(figures):
    # The levels of the laws that hold: -2/3 for the gases past 10 t_stick, 0 and
    # -2 for the cooling gas (r = 0.95), whose 400 particles leave the sticky law no window.
    for run, held, absent in (("gas", [-2 / 3], []), ("sweep", [-2 / 3], []), ("cooling", [0.0, -2.0], [-2 / 3])):
        fig = figures[run]["temperature.png"]
        exponent = [ax for ax in panels(fig) if r"d\ln T/d\ln t" in ax.get_ylabel()]
        assert len(exponent) == 1
        levels = [line.get_ydata()[0] for line in exponent[0].get_lines() if len(set(line.get_ydata())) == 1]
        for level in held:
            assert any(abs(x - level) < 1e-12 for x in levels), (run, level, levels)
        for level in absent:
            assert not any(abs(x - level) < 1e-12 for x in levels), (run, level, levels)


def test_clusters_against_the_exact_count_masses_and_shocks(runs, figures):
    fig = figures["gas"]["clusters.png"]
    legend = the_legend(fig)
    assert any("shock-mass law" in t for t in legend)
    assert "a matched pair (shock to cluster)" in legend or "cluster without a shock" in legend
    # The exact count in time is the file's: the shocks the engine's count counts (heavier than 1.5 particles).
    drawn = [line for ax in panels(fig) for line in ax.get_lines()
             if line.get_label().startswith("exact: shocks heavier than 1.5 particles")]
    assert len(drawn) == 1
    with open_result(runs["gas"]) as f:
        coefficient = f["particles/analysis"].attrs["n_shocks_exact_coefficient"]
        t, exact = f["particles/t"][:], f["particles/analysis/n_clusters_exact"][:]
    assert abs(coefficient / 600 - 1.9157) < 5e-5  # 1.916 N for uniform velocities on [-1, 1]
    late = np.isin(t, drawn[0].get_xdata())
    assert late.sum() == len(drawn[0].get_xdata()) >= 2
    assert np.allclose(drawn[0].get_ydata(), exact[late], rtol=0, atol=0)


def test_without_a_comparison_the_heaviest_cluster_is_marked_on_the_shock(runs, figures):
    summary = read_summary(runs["sine"])
    x, m = summary["analysis"]["heaviest_cluster_x"], summary["analysis"]["heaviest_cluster_m"]
    assert abs(x - summary["continuum"]["hopf_lax"]["heaviest_shock_x"]) < 1e-2  # on the shock, within a cell (1/128)
    fig = figures["sine"]["fields.png"]
    marks = [line for ax in panels(fig) for line in ax.get_lines()
             if line.get_label().startswith("heaviest cluster of the gas")]
    assert len(marks) == 2 and all(np.allclose(line.get_xdata(), [x]) for line in marks)
    assert f"mass {m:.4g}" in marks[0].get_label()


def test_the_wave_in_time_against_the_exact_breaking_time(runs, figures):
    fig = figures["sine"]["evolution.png"]
    legend = the_legend(fig)
    exact = [t for t in legend if t.startswith("exact: t* - t")]
    assert len(exact) == 1 and f"{1 / (2 * np.pi):.4g}" in exact[0]  # t* = 1 / max(-v0') = 1 / (2 pi)
    # A sine fills its ring: its lobes meet each other's shocks and lose area, and
    # up to t = 0.5 = 3.1 t* it is no sawtooth yet: neither law is drawn over it.
    assert not any(t.startswith("theory") for t in legend), legend
    titles = [ax.get_title() for ax in panels(fig)]
    assert "lobe areas: no theory for this scene" in titles and "decay: no theory for this scene" in titles
    for ax in panels(fig):
        assert ax.get_legend() is None


def test_the_regimes_of_a_cooling_gas(figures):
    fig = figures["cooling"]["regimes.png"]
    legend = the_legend(fig)
    for regime in ("elastic", "homogeneous cooling", "sticky gas (clusters)"):
        assert f"theory: {regime} regime" in legend
    assert any(t.startswith("measured t_stick") for t in legend)
    assert any(t.startswith("theory: homogeneous cooling") for t in legend)


def test_a_few_bodies_are_drawn_without_the_laws_of_the_gas(figures):
    drawn = figures["few"]
    assert "regimes.png" not in drawn
    fig = drawn["temperature.png"]
    (ax,) = panels(fig)
    assert ax.get_yscale() == "linear" and ax.get_ylim()[0] == 0  # T = 0 of a collapse stays on the axis
    legend = the_legend(fig)
    assert not any(t.startswith(("exact", "guide", "theory", "fit")) for t in legend), legend
    if "clusters.png" in drawn:
        assert not any(t.startswith(("exact", "guide")) for t in the_legend(drawn["clusters.png"]))


def test_a_constant_amplitude_is_not_magnified_to_its_rounding(figures):
    fig = figures["step"]["evolution.png"]
    (amplitude,) = [ax for ax in panels(fig) if ax.get_ylabel().startswith("amplitude")]
    low, high = amplitude.get_ylim()
    assert high / low >= 2  # 0.75 +- 1e-16 would otherwise fill the panel with rounding
    texts = [t.get_text() for ax in fig.axes for t in ax.texts]
    assert any(t.startswith("no breaking to show") for t in texts)  # a shock from t = 0


def test_the_script_writes_every_picture(runs):
    out = runs["gas"]
    subprocess.run(["/usr/bin/python3", os.path.join(PLOTS, "plot_result.py"), str(out)], check=True)
    for name in ("temperature.png", "velocity_distribution.png", "fields.png", "clusters.png", "spacetime.png"):
        assert (out / name).stat().st_size > 10000, name


def test_the_space_time_title_says_which_world_lines_are_drawn(figures):
    (ax,) = figures["gas"]["spacetime.png"].axes
    assert "world lines of every particle" in ax.get_title()  # N = 600: every one recorded and drawn
    assert shown_lines(np.array([0, 50, 100])) == "every 50th particle"
    assert shown_lines(np.array([0, 50, 100, 151])) == "4 particles, about every 50.3th"
