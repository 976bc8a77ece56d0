"""The page of `shockgas stats` (plots/plot_statistics.py), drawn from the files of
small runs and inspected artist by artist: a unit on every axis, a legend on every
panel, the exact laws as black lines only where the start has them, the data as
points with error bars. The command is $SHOCKGAS (CTest sets it)."""
import os
import subprocess
import sys

import matplotlib
import pytest
from matplotlib.colors import to_rgba

matplotlib.use("Agg")
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "plots"))
from plot_statistics import figure  # noqa: E402

COMMAND = os.environ.get("SHOCKGAS", os.path.join(ROOT, "build", "shockgas"))
WHITE_NOISE = """[initial]
N = 3000
velocities = "uniform"
seed = 4
[particles]
r = 0
solver = "hull"
t_end = 100
samples = 2
realizations = 4
"""
SINE = """[initial]
N = 3000
velocities = "expression"
v0 = "sin(2*pi*x)"
domain = 1
[particles]
r = 0
solver = "hull"
t_end = 0.5
samples = 2
realizations = 2
"""


def statistics_of(tmp_path, scene):
    (tmp_path / "scene.toml").write_text(scene)
    for args in (["run", tmp_path / "scene.toml", "--out", tmp_path / "run", "-q", "--no-plots"],
                 ["stats", tmp_path / "run", "--out", tmp_path / "stats", "-q"]):
        subprocess.run([COMMAND, *map(str, args)], check=True, capture_output=True)
    assert (tmp_path / "stats" / "statistics.png").stat().st_size > 0
    return figure(str(tmp_path / "stats"))


def black_lines(ax):
    return [line for line in ax.get_lines() if to_rgba(line.get_color()) == to_rgba("black")]


@pytest.mark.parametrize("scene, laws", [(WHITE_NOISE, 2), (SINE, 0)])
def test_every_panel_has_units_a_legend_and_the_laws_where_they_hold(tmp_path, scene, laws):
    fig = statistics_of(tmp_path, scene)
    axes = fig.axes
    assert len(axes) == 3
    for ax in axes:
        assert "[" in ax.get_xlabel() and "[" in ax.get_ylabel(), ax.get_title()
        if ax.containers:  # the data as points with error bars, and their legend
            assert ax.get_legend() is not None, ax.get_title()
        else:  # a sine holds one shock: no gaps to draw, and the page says so
            assert [t.get_text() for t in ax.texts] == ["none: fewer than two clusters in every realization"]
    assert all(ax.containers for ax in axes[:2])
    drawn = [ax for ax in axes if black_lines(ax)]
    assert len(drawn) == laws  # masses and velocities for white noise; none for a sine
    assert not black_lines(axes[2])  # the spacing has no exact law in shockgas
    for ax in axes[:2]:
        texts = [t.get_text() for t in ax.texts]
        assert ("no exact law for this start" in texts) == (laws == 0)
