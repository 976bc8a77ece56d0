"""Shocks against clusters on numpy arrays, against the scene's comparison."""

import numpy as np

import shockgas
from conftest import assert_same_bits

SCENE = {
    "initial": {"N": 4000, "seed": 9},
    "particles": {"r": 0.5, "delta": 1e-2, "t_end": 1000.0, "samples": 10},
    "continuum": {"solvers": ["hopf_lax"], "cells": 1024},
    "compare": {},
}


def test_a_snapshot_on_arrays_equals_the_scenes_comparison():
    r = shockgas.run(SCENE)
    d = r.datasets
    x, v, m = (d["/initial/" + c] for c in "xvm")
    field = shockgas.continuum.solve("hopf_lax", v, x=x, m=m, cells=1024, t_end=1000.0)
    final = [d["/particles/final/" + c] for c in "xvm"]
    c = shockgas.compare.snapshot(*final, field, N=4000, r=0.5, delta=1e-2)
    assert c.n_shocks == r.figures["compare.n_shocks"] and c.n_clusters == r.figures["compare.n_clusters"]
    assert c.match.matched_mass_fraction == r.figures["compare.matched_mass_fraction"]
    for ours, theirs in [(c.clusters.x, "clusters_x"), (c.clusters.m, "clusters_m"), (c.shocks.x, "shocks_x"),
                         (c.match.position_error, "matched_position_error"),
                         (c.particle_fields.rho, "rho_particles"),
                         (c.sawtooth.slope_times_t, "sawtooth_slope_times_t")]:
        assert_same_bits(ours, d["/compare/" + theirs], theirs)


def test_the_steps_of_a_snapshot_compose_to_it():
    r = shockgas.run(SCENE)
    d = r.datasets
    final = [d["/particles/final/" + c] for c in "xvm"]
    x, v, m = (d["/initial/" + c] for c in "xvm")
    field = shockgas.continuum.solve("hopf_lax", v, x=x, m=m, cells=1024, t_end=1000.0)
    whole = shockgas.compare.snapshot(*final, field, N=4000, r=0.5, delta=1e-2)
    clusters = shockgas.compare.find_clusters(*final, L=4000.0, t=1000.0, r=0.5, delta=1e-2)
    assert_same_bits(clusters.x, whole.clusters.x, "clusters")
    matched = shockgas.compare.match(field.shocks, clusters, 4000.0, min_mass=whole.min_mass)
    assert matched.matched_mass_fraction == whole.match.matched_mass_fraction
    assert_same_bits(matched.position_error, whole.match.position_error, "pairs")
    grid = shockgas.compare.deposit(*final, length=4000.0, cells=1024)
    assert_same_bits(grid.rho, whole.particle_fields.rho, "deposit")


def test_shocks_of_an_exact_sawtooth_are_found_where_they_are():
    # Ramps of slope 1/t between shocks at 0.3 and 0.7 on [0, 1), t = 2: the
    # detection is exact for ramps of equal slope (shockgas/compare/shock_detection.hpp).
    n, t = 200, 2.0
    edges = np.linspace(0, 1, n + 1)

    def potential(x):  # int v, v = (x - q)/t with q = 0.5 on (0.3, 0.7), q = 0 / 1 outside
        ramp = lambda a, b, q: ((b - q) ** 2 - (a - q) ** 2) / (2 * t)
        a, b, c = np.minimum(x, 0.3), np.clip(x, 0.3, 0.7), np.clip(x, 0.7, 1.0)
        return ramp(0, a, 0.0) + ramp(0.3, b, 0.5) + ramp(0.7, c, 1.0)

    v = np.diff(potential(edges)) * n
    shocks = shockgas.compare.detect_shocks(v, 1.0)
    np.testing.assert_allclose(shocks.x, [0.3, 0.7], atol=1e-12)
    np.testing.assert_allclose(shocks.jump, [-0.25, -0.25], atol=1e-12)
    fit = shockgas.compare.sawtooth(v, 1.0, t, shocks.x)
    np.testing.assert_allclose(fit.slope_times_t, 1.0, atol=1e-9)
