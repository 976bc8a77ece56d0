"""The pictures of docs/paper.md drawn from the kept runs (data/paper-runs/):
scripts/plot_fig1_runs.py and scripts/plot_tail.py read those files as they
are kept and draw every picture the page shows, the exact law black and dashed
and named "exact", a label on every axis."""
import os
import subprocess
import sys

import matplotlib
import pytest

matplotlib.use("Agg")
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SCRIPTS = os.path.join(ROOT, "scripts")
RUNS = os.path.join(ROOT, "data", "paper-runs")
sys.path.insert(0, SCRIPTS)
import plot_tail  # noqa: E402


def run(script, *args):
    subprocess.run([sys.executable, os.path.join(SCRIPTS, script), *args], check=True)


def test_fig1_picture_from_the_kept_runs(tmp_path):
    run("plot_fig1_runs.py", os.path.join(RUNS, "fig1"), "--out", str(tmp_path))
    assert os.path.getsize(tmp_path / "fig1-paper-size.png") > 10000


def test_tail_pictures_from_the_kept_runs(tmp_path):
    tail = os.path.join(RUNS, "tail")
    dirs = sorted(os.path.join(tail, d) for d in os.listdir(tail))
    run("plot_tail.py", *dirs, "--out", str(tmp_path))
    # docs/paper.md shows these four
    for name in ["tail-phi-r0.png", "tail-local-r0.png", "tail-windows.png", "tail-local-r09.png"]:
        assert os.path.getsize(tmp_path / name) > 10000, name


@pytest.fixture
def capture(monkeypatch):
    """The figures plot_tail draws, kept open instead of saved."""
    figures = []
    monkeypatch.setattr(plot_tail.plt, "close", lambda fig: figures.append(fig))
    return figures


def test_tail_exact_law_is_black_dashed_and_axes_are_labelled(tmp_path, capture):
    phi = plot_tail.read(os.path.join(RUNS, "tail", "hull-N1e7", "tail_phi.csv"))
    plot_tail.plot_phi(phi, 0.0, 1e7, str(tmp_path))
    plot_tail.plot_local(phi, 0.0, 1e7, str(tmp_path))
    figures = [f for f in capture if hasattr(f, "axes")]  # not plt.close("all")
    assert len(figures) == 2
    for fig in figures:
        ax = fig.axes[0]
        assert ax.get_xlabel() and ax.get_ylabel()
        exact = [l for l in ax.get_lines() if l.get_label().startswith("exact")]
        assert exact, "no exact law drawn"
        assert exact[0].get_color() == "k" and exact[0].get_linestyle() == "--"
