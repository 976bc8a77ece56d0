"""The pictures of a run directory, read only from its result files (result.h5,
summary.json): figures() builds them (the tests inspect these), draw_all()
writes them as PNGs. One module per picture."""
import os

from .clusters import figure_clusters
from .common import is_gas
from .distribution import figure_distribution
from .evolution import figure_evolution
from .few_bodies import figure_few_bodies
from .fields import figure_fields
from .log_ticks import install as install_log_ticks
from .regimes import figure_regimes
from .run_files import RESULT, SUMMARY, open_result, read_summary
from .saving import save
from .spacetime import figure_spacetime
from .sweep import figure_sweep_distribution, figure_sweep_temperature
from .temperature import figure_temperature

install_log_ticks()  # tick labels of log axes as text, not mathtext (log_ticks.py)

SOURCE = f"{RESULT}, {SUMMARY}"  # what the pictures are drawn from (PNG text Source)


def called_for(f, summary):
    """Every picture the result calls for, {file name: build}, build(f, summary)
    giving its figure (None: too little data to draw). Nothing is drawn here."""
    wanted = {}
    if "sweep" in f:
        wanted["temperature.png"] = figure_sweep_temperature
        wanted["velocity_distribution.png"] = lambda f, summary: figure_sweep_distribution(f)
    if "particles/T" in f:
        wanted["temperature.png"] = figure_temperature
    if not is_gas(summary):
        wanted["temperature.png"] = lambda f, summary: figure_few_bodies(f)
    if "particles/histogram" in f:
        wanted["velocity_distribution.png"] = lambda f, summary: figure_distribution(f)
    if "particles/spacetime" in f:
        wanted["spacetime.png"] = lambda f, summary: figure_spacetime(f)
    if "continuum" in f:
        wanted["fields.png"] = figure_fields
    if "particles/n_clusters" in f or "compare/cluster_mass_edges" in f:
        wanted["clusters.png"] = figure_clusters
    if "animation/evolution" in f:
        wanted["evolution.png"] = figure_evolution
    if "particles/analysis" in f:
        wanted["regimes.png"] = figure_regimes
    return wanted


def figures(f, summary):
    """Every picture the result calls for: {file name: matplotlib figure}."""
    drawn = {name: build(f, summary) for name, build in called_for(f, summary).items()}
    return {name: fig for name, fig in drawn.items() if fig is not None}


def draw(f, summary, out_dir, name):
    """Writes the picture `name` (one of called_for's) into out_dir, if it has data to show."""
    fig = called_for(f, summary)[name](f, summary)
    if fig is not None:
        save(fig, os.path.join(out_dir, name), SOURCE)


def draw_all(out_dir):
    """Every picture of run directory out_dir, one after the other."""
    summary = read_summary(out_dir, missing={})
    with open_result(out_dir) as f:
        for name in called_for(f, summary):
            draw(f, summary, out_dir, name)
