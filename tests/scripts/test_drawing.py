"""The drawing of a run by one process and its workers
(plots/shockplot/drawing.py): two workers write the same files, byte for byte,
as one that draws them one after the other; a picture that fails leaves the
others written and ends the drawing with its one line; the animation is drawn
by the same process when asked. The command is $SHOCKGAS (CTest sets it)."""
import os
import subprocess
import sys

import matplotlib
import pytest

matplotlib.use("Agg")
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "plots"))
from shockplot import drawing  # noqa: E402

# Particles with every picture of a gas, a continuum solver and frames.
SCENE = """[initial]
N = 500
seed = 5
[particles]
r = 0.5
delta = 1e-2
t_end = 200
samples = 12
histogram_bins = 20
spacetime = true
spacetime_frames = 20
[continuum]
solvers = ["hopf_lax"]
cells = 500
[compare]
solver = "hopf_lax"
fit_window = 10
[output]
plots = false
animation = true
animation_frames = 9
"""
PICTURES = {"temperature.png", "velocity_distribution.png", "spacetime.png", "fields.png", "clusters.png"}


def pictures(d):
    return {name: (d / name).read_bytes() for name in os.listdir(d) if name.endswith(".png")}


def copy_of(out, name):
    """A new run directory holding out's result files alone."""
    d = out.parent / name
    d.mkdir()
    for f in ("result.h5", "summary.json"):
        (d / f).write_bytes((out / f).read_bytes())
    return d


@pytest.fixture(scope="module")
def out(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("drawing")
    (tmp / "scene.toml").write_text(SCENE)
    command = os.environ.get("SHOCKGAS", os.path.join(ROOT, "build", "shockgas"))
    subprocess.run([command, "run", str(tmp / "scene.toml"), "--out", str(tmp / "run"), "-q"], check=True,
                   stdout=subprocess.DEVNULL)
    return tmp / "run"


def test_two_workers_write_what_one_writes(out):
    one, two = copy_of(out, "one"), copy_of(out, "two")
    assert drawing.draw_run(str(one), workers=1) == (0, "")
    assert drawing.draw_run(str(two), workers=2) == (0, "")
    assert set(pictures(one)) >= PICTURES
    assert pictures(two) == pictures(one)


def test_the_animation_is_drawn_beside_the_pictures(out):
    d = copy_of(out, "animated")
    assert drawing.draw_run(str(d), animation=True, workers=2) == (0, "")
    assert set(pictures(d)) >= PICTURES | {"animation.png"}
    assert (d / "animation.gif").stat().st_size > 0
    assert not [name for name in os.listdir(d) if name.endswith(".partial")]


def test_a_failed_picture_leaves_the_others_and_says_why(out, monkeypatch):
    d = copy_of(out, "failing")
    real = drawing.draw

    def draw(f, summary, out_dir, name):
        if name == "fields.png":
            raise ValueError("no fields today")
        real(f, summary, out_dir, name)

    monkeypatch.setattr(drawing, "draw", draw)  # the workers fork after it: they draw with it too
    assert drawing.draw_run(str(d), workers=2) == (drawing.FAILED, "fields.png: ValueError: no fields today")
    assert "fields.png" not in pictures(d) and set(pictures(d)) >= PICTURES - {"fields.png"}
