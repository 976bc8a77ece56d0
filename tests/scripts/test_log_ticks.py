"""Log-axis tick labels as plain text (plots/shockplot/log_ticks.py): each form
of matplotlib's mathtext label of a log or symlog axis read as text, and the
axes of a drawn figure carrying no mathtext tick label."""
import os
import sys

import matplotlib
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "plots"))

from shockplot import log_ticks  # noqa: E402


@pytest.mark.parametrize("math, text", [
    (r"$\mathdefault{10^{3}}$", "10³"),
    (r"$\mathdefault{10^{-2}}$", "10⁻²"),
    (r"$\mathdefault{10^{0}}$", "10⁰"),
    (r"$\mathdefault{2\times10^{2}}$", "2×10²"),
    (r"$\mathdefault{-10^{1}}$", "−10¹"),
    (r"$\mathdefault{0}$", "0"),
    (r"$\mathdefault{-1.5}$", "−1.5"),
    ("", ""),
    ("plain", "plain"),
    (r"$\mathdefault{e^{2}}$", r"$\mathdefault{e^{2}}$"),  # another form: left as written
])
def test_each_label_form_reads_as_text(math, text):
    assert log_ticks.as_text(math) == text


def test_the_installed_scales_label_log_and_symlog_axes_in_text():
    log_ticks.install()
    fig, (a, b) = plt.subplots(1, 2)
    a.set_xscale("log")
    a.set_yscale("log")
    a.plot([0.01, 30000], [0.003, 2e4])
    b.set_yscale("symlog", linthresh=1.0)
    b.plot([0, 1], [-100, 100])
    fig.canvas.draw()
    labels = [t.get_text() for ax in (a, b) for axis in (ax.xaxis, ax.yaxis)
              for t in axis.get_ticklabels(which="both") if t.get_text()]
    plt.close(fig)
    assert "10⁻²" in labels and "10⁴" in labels and "−10²" in labels
    assert not [t for t in labels if "$" in t], labels


def test_a_log_colorbar_labelled_in_text():
    import numpy as np
    from matplotlib.colors import LogNorm
    fig, ax = plt.subplots()
    mesh = ax.pcolormesh(np.array([[1.0, 10.0], [100.0, 1000.0]]), norm=LogNorm(1.0, 1000.0))
    cb = fig.colorbar(mesh, ax=ax)
    log_ticks.label_colorbar(cb)
    fig.canvas.draw()
    labels = [t.get_text() for t in cb.ax.yaxis.get_ticklabels() if t.get_text()]
    plt.close(fig)
    assert "10²" in labels, labels
    assert not [t for t in labels if "$" in t], labels
