"""The pictures of docs/paper.md drawn from the kept runs (data/paper-runs/):
scripts/paper/plot_fig1_runs.py and plots/plot_tail.py read those files as they
are kept and draw every picture the page shows, the exact law black and dashed
and named "exact", a label on every axis."""
import os
import subprocess
import sys

import matplotlib
import pytest

matplotlib.use("Agg")
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
PLOTS = os.path.join(ROOT, "plots")
PAPER = os.path.join(ROOT, "scripts", "paper")
RUNS = os.path.join(ROOT, "data", "paper-runs")
sys.path[:0] = [PLOTS, PAPER]
import plot_tail  # noqa: E402


def run(script, *args):
    """A script of scripts/paper/, or of plots/ (the tail's charts)."""
    folder = PLOTS if os.path.exists(os.path.join(PLOTS, script)) else PAPER
    subprocess.run([sys.executable, os.path.join(folder, script), *args], check=True)


def test_fig1_picture_from_the_kept_runs(tmp_path):
    run("plot_fig1_runs.py", os.path.join(RUNS, "fig1"), "--out", str(tmp_path))
    assert os.path.getsize(tmp_path / "fig1-paper-size.png") > 10000
    assert os.path.getsize(tmp_path / "fig1-rpos-paper-size.png") > 10000  # r = 0.5, 0.9, 0.99 are kept


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


def test_fig2_picture_from_the_kept_runs(tmp_path):
    run("plot_fig2_runs.py", os.path.join(RUNS, "fig2"), "--out", str(tmp_path))
    assert os.path.getsize(tmp_path / "fig2-paper-size.png") > 10000


def test_fig4_picture_from_kept_histograms(tmp_path):
    """A kept run as collect_paper_run.py writes it: a normal Phi with the exact column."""
    import csv
    import json
    import math

    for r in (0.0, 0.5):
        d = tmp_path / "runs" / ("events-r%g-R50" % r)
        d.mkdir(parents=True)
        (d / "summary.json").write_text(json.dumps({"initial": {"N": 100000},
                                                    "particles": {"r": r, "realizations": 50}}))
        with open(d / "histogram.csv", "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["t", "z", "density", "density_stderr", "exact"])
            for t in (1e2, 1e3, 1e4):
                for k in range(80):
                    z = -3.95 + 0.1 * k
                    p = math.exp(-z * z / 0.426) / math.sqrt(math.pi * 0.426)
                    w.writerow([t, z, p * (1 + 0.01 * r), 0.01 * p, p])
    run("plot_fig4_runs.py", str(tmp_path / "runs"), "--out", str(tmp_path))
    assert os.path.getsize(tmp_path / "fig4-paper-size.png") > 10000


def test_table_exponents_and_interpolation_are_exact_on_a_power_law():
    import paper_tables
    import plot_fig2_runs

    rows = [(10 ** (k / 10), 0.2129 * 10 ** (-2 * k / 30), 0.0) for k in range(0, 61)]  # T = 0.2129 t^(-2/3)
    for lo in (1e2, 1e3, 1e4, 1e5):
        assert abs(paper_tables.decade_slope(rows, lo) + 2 / 3) < 1e-12
    assert paper_tables.decade_slope(rows, 1e6) is None  # the samples end at 10^6
    series = [(t, T) for t, T, _ in rows]
    assert abs(plot_fig2_runs.interpolate(series, 3000.0) / (0.2129 * 3000.0 ** (-2 / 3)) - 1) < 1e-12
    assert plot_fig2_runs.interpolate(series, 2e6) is None


def test_tables_from_the_kept_runs(capsys):
    import paper_tables

    sys.argv = ["paper_tables.py", RUNS]
    paper_tables.main()
    out = capsys.readouterr().out
    assert "`d1e-2-sticky-R5` | delta = 0.01, sticky below it | 1e+06 × 5, 1e+06" in out
    assert "`hull-r0-R40` | exact sticky gas r = 0, the same initial state | 1e+06 × 40" in out
    assert "`hull-r0-R1000` | 0 | 1000 × 1e+06 | -0.6671 ± 0.0002" in out


def test_kept_series_read_back_as_written(tmp_path):
    """T.csv (shockplot/run_files.py) holds every number of the result file
    exactly (repr of doubles) and leaves the samples not reached out."""
    import h5py
    import numpy as np
    from shockplot import run_files

    t = np.array([1.0, 10.0, 100.0])
    each = np.array([[0.5, 1 / 3, np.nan], [0.25, 0.1 + 0.2, np.nan]])
    with h5py.File(tmp_path / "result.h5", "w") as h5:
        h5["particles/t"] = t
        h5["particles/T"] = np.array([0.375, np.pi, np.nan])
        h5["particles/T_stderr"] = np.array([0.125, np.e, np.nan])
        h5["particles/realizations/T"] = each
        run_files.write_series(h5, str(tmp_path / run_files.SERIES))
    rows = run_files.read_series(str(tmp_path))
    assert [r["t"] for r in rows] == [1.0, 10.0]
    assert [r["T"] for r in rows] == [0.375, np.pi]
    assert run_files.realization_columns(rows) == ["T_0", "T_1"]
    assert [r["T_1"] for r in rows] == [0.25, 0.1 + 0.2]
    assert run_files.T_series(str(tmp_path)) == [(1.0, 0.375, 0.125), (10.0, np.pi, np.e)]


def test_fig2_draws_each_rule_and_delta_once(monkeypatch, tmp_path):
    """Runs of one rule and delta share realization 0: one curve and one legend
    entry each, in both panels (the kept runs hold two sticky runs of each delta)."""
    import plot_fig2_runs

    figures = []
    monkeypatch.setattr(plot_fig2_runs, "save", lambda fig, path, source: figures.append(fig))
    monkeypatch.setattr(sys, "argv", ["plot_fig2_runs.py", os.path.join(RUNS, "fig2"), "--out", str(tmp_path)])
    plot_fig2_runs.main()
    (fig,) = figures
    for ax in fig.axes:
        labels = [l for l in ax.get_legend_handles_labels()[1]]
        assert len(labels) == len(set(labels)), labels
        assert ax.get_xlabel().endswith("[time]") and ax.get_ylabel()
    right = fig.axes[1].get_legend_handles_labels()[1]
    assert "delta = 0.01, sticky below it, 10 paired" in right
