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
from .regimes import figure_regimes
from .run_files import RESULT, SUMMARY, open_result, read_summary
from .saving import save
from .spacetime import figure_spacetime
from .sweep import figure_sweep_distribution, figure_sweep_temperature
from .temperature import figure_temperature

SOURCE = f"{RESULT}, {SUMMARY}"  # what the pictures are drawn from (PNG text Source)


def figures(f, summary):
    """Every picture the result calls for: {file name: matplotlib figure}."""
    drawn = {}
    if "sweep" in f:
        drawn["temperature.png"] = figure_sweep_temperature(f, summary)
        drawn["velocity_distribution.png"] = figure_sweep_distribution(f)
    if "particles/T" in f:
        drawn["temperature.png"] = figure_temperature(f, summary)
    if not is_gas(summary):
        drawn["temperature.png"] = figure_few_bodies(f)
    if "particles/histogram" in f:
        drawn["velocity_distribution.png"] = figure_distribution(f)
    if "particles/spacetime" in f:
        drawn["spacetime.png"] = figure_spacetime(f)
    if "continuum" in f:
        drawn["fields.png"] = figure_fields(f, summary)
    if "particles/n_clusters" in f or "compare/cluster_mass_edges" in f:
        drawn["clusters.png"] = figure_clusters(f, summary)
    if "animation/evolution" in f:
        drawn["evolution.png"] = figure_evolution(f, summary)
    if "particles/analysis" in f:
        drawn["regimes.png"] = figure_regimes(f, summary)
    return {name: fig for name, fig in drawn.items() if fig is not None}


def draw_all(out_dir):
    summary = read_summary(out_dir, missing={})
    with open_result(out_dir) as f:
        for name, fig in figures(f, summary).items():
            save(fig, os.path.join(out_dir, name), SOURCE)
