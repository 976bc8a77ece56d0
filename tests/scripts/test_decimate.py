"""The run's pictures keep their content when heavy series are drawn decimated
(plots/shockplot/decimate.py): every line of every figure hands the renderer
points whose extents, whose lowest and highest point in each pixel column, and
whose first and last point are those of the whole series (the data before), and
a line of markers covers the same pixels. Checked on synthetic series and on the
figures of a run of 8000 particles and cells, where the decimation thins (a test
that it does). The command is $SHOCKGAS (CTest sets it)."""
import os
import subprocess
import sys

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "plots"))
from shockplot.decimate import LEAST, Decimated, decimated, kept  # noqa: E402
from shockplot.pictures import figures as figures_from  # noqa: E402
from shockplot.run_files import open_result, read_summary  # noqa: E402
from shockplot.saving import DPI  # noqa: E402

# Heavy enough that the fields' series pass LEAST, small enough for a unit
# test (about a second); late enough for fewer than 50 shocks (N t^(-2/3) = 38),
# so that fields.png draws the whole ring, not a window of it.
HEAVY = """[initial]
N = 8000
seed = 3
[particles]
r = 0.5
delta = 1e-2
t_end = 3000
samples = 12
histogram_bins = 24
spacetime = true
spacetime_frames = 20
[continuum]
solvers = ["hopf_lax", "godunov"]
cells = 8000
[compare]
solver = "hopf_lax"
fit_window = 100
[output]
plots = false
"""


def pixel_columns(line, x, y):
    """{pixel column: (lowest, highest) pixel row} of the finite points (x, y) of line."""
    px, py = line.get_transform().transform(np.column_stack([x, y])).T
    ok = np.isfinite(px) & np.isfinite(py)
    columns = {}
    for c, r in zip(np.floor(px[ok]).astype(int), py[ok]):
        lo, hi = columns.get(c, (r, r))
        columns[c] = (min(lo, r), max(hi, r))
    return columns


def assert_same_content(line):
    """The points line draws (kept) against its whole series: extents, each
    pixel column's extremes, first and last point, the pixels its markers cover."""
    x = np.asarray(line.get_xdata(orig=True), float)
    y = np.asarray(line.get_ydata(orig=True), float)
    keep = kept(line, np.column_stack([x, y]))
    if keep is None:
        return 0
    ok = np.isfinite(x) & np.isfinite(y)
    kx, ky = x[keep], y[keep]
    kok = np.isfinite(kx) & np.isfinite(ky)
    assert (np.min(kx[kok]), np.max(kx[kok])) == (np.min(x[ok]), np.max(x[ok]))
    assert (np.min(ky[kok]), np.max(ky[kok])) == (np.min(y[ok]), np.max(y[ok]))
    assert keep[0] == 0 and keep[-1] == len(x) - 1
    if line.get_linestyle() not in ("None", "none", " ", ""):
        assert pixel_columns(line, kx, ky) == pixel_columns(line, x, y)
        assert np.count_nonzero(~np.isfinite(kx) | ~np.isfinite(ky)) == np.count_nonzero(~ok)  # gaps kept
    if line.get_marker() not in (None, "None", "none", " ", ""):
        cells = lambda px, py: set(zip(np.floor(px).astype(int), np.floor(py).astype(int)))  # noqa: E731
        whole = line.get_transform().transform(np.column_stack([x[ok], y[ok]])).T
        drawn = line.get_transform().transform(np.column_stack([kx[kok], ky[kok]])).T
        assert cells(*drawn) == cells(*whole)
    return len(x) - len(keep)


def drawn_figure(plot):
    fig, ax = plt.subplots(figsize=(6, 4), dpi=DPI)
    (line,) = decimated(plot(ax))
    fig.canvas.draw()  # the transform of the draw the picture is saved at
    return fig, line


def test_a_line_keeps_each_pixel_columns_extremes_and_its_gaps():
    rng = np.random.default_rng(1)
    x = np.arange(20000.0)
    y = np.cumsum(rng.normal(size=x.size))
    y[[5000, 5001, 12000]] = np.nan  # two gaps: a line broken there
    fig, line = drawn_figure(lambda ax: ax.plot(x, y, lw=0.5))
    thinned = assert_same_content(line)
    width = fig.get_size_inches()[0] * DPI
    assert len(x) - thinned <= 4 * width + 9  # four points a column, each gap with its two neighbours
    plt.close(fig)


def test_markers_cover_the_same_pixels():
    rng = np.random.default_rng(2)
    fig, line = drawn_figure(lambda ax: ax.plot(rng.random(20000), rng.normal(size=20000), ".", ms=1))
    assert assert_same_content(line) > 0
    plt.close(fig)


def test_a_light_series_is_drawn_whole():
    fig, line = drawn_figure(lambda ax: ax.plot(np.arange(LEAST - 1.0), np.zeros(LEAST - 1)))
    assert kept(line, np.column_stack([line.get_xdata(), line.get_ydata()])) is None
    plt.close(fig)


def test_the_figure_keeps_the_whole_series_after_a_draw():
    x = np.linspace(0, 1, 10000)
    fig, line = drawn_figure(lambda ax: ax.plot(x, np.sin(40 * x)))
    assert np.array_equal(line.get_xdata(), x) and np.array_equal(line.get_ydata(), np.sin(40 * x))
    plt.close(fig)


@pytest.fixture(scope="module")
def heavy_figures(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("decimate")
    (tmp / "heavy.toml").write_text(HEAVY)
    command = os.environ.get("SHOCKGAS", os.path.join(ROOT, "build", "shockgas"))
    subprocess.run([command, "run", str(tmp / "heavy.toml"), "--out", str(tmp / "heavy"), "-q"], check=True,
                   stdout=subprocess.DEVNULL)
    with open_result(tmp / "heavy") as f:
        figures = figures_from(f, read_summary(tmp / "heavy"))
    yield figures
    for fig in figures.values():
        plt.close(fig)


def test_every_picture_of_a_heavy_run_draws_the_content_of_its_series(heavy_figures):
    thinned = {}
    for name, fig in heavy_figures.items():
        fig.set_dpi(DPI)
        fig.canvas.draw()
        lines = [line for ax in fig.axes for line in ax.get_lines() if isinstance(line, Decimated)]
        thinned[name] = sum(assert_same_content(line) for line in lines)
    assert thinned["fields.png"] > 0, "the fields' series of 8000 cells are thinned: the test sees decimation"
