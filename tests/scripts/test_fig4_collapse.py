"""scripts/paper/fig4_collapse.py on synthetic sweeps whose answer is known: two
restitutions drawn from one distribution collapse to the noise floor, a shifted
one does not, and a group's distance is the mean of its pairs' L1 distances
(as analysis.velocity_collapse_distance defines it). Seeded."""
import json
import math
import os
import sys

import h5py
import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "paper"))
import fig4_collapse  # noqa: E402

Z_MAX, BINS, TIMES = 4.0, 80, [1e3, 1e4, 1e5]
REALIZATIONS, CLUSTERS = 50, 400


def histograms(rng, shift):
    """[realization, time, bin] densities of CLUSTERS normal samples each."""
    edges = np.linspace(-Z_MAX, Z_MAX, BINS + 1)
    dz = edges[1] - edges[0]
    out = np.empty((REALIZATIONS, len(TIMES), BINS))
    for i in range(REALIZATIONS):
        for k in range(len(TIMES)):
            counts, _ = np.histogram(rng.normal(shift, 0.46, CLUSTERS), bins=edges)
            out[i, k] = counts / (CLUSTERS * dz)
    return out


def write_variant(root, name, r, h):
    d = root / name
    d.mkdir()
    z = np.linspace(-Z_MAX, Z_MAX, BINS + 1)
    with h5py.File(d / "result.h5", "w") as f:
        f["particles/histogram/t"] = np.array(TIMES)
        f["particles/histogram/z"] = 0.5 * (z[1:] + z[:-1])
        f["particles/realizations/histogram_density"] = h.reshape(REALIZATIONS, -1)
    summary = {"initial": {"N": 100000}, "particles": {"r": r}, "analysis": {}}
    (d / "summary.json").write_text(json.dumps(summary))


def sweep(tmp_path, shifts, seed=1999):
    rng = np.random.default_rng(seed)
    for k, (r, shift) in enumerate(shifts):
        write_variant(tmp_path, "%d-r" % k, r, histograms(rng, shift))
    return fig4_collapse.collapse(str(tmp_path), 1e3)


def group(result, kind, **where):
    return [g for g in result["groups"] if g["kind"] == kind and all(g[k] == v for k, v in where.items())][0]


def test_one_distribution_collapses_to_its_noise_floor(tmp_path):
    result = sweep(tmp_path, [(0.0, 0.0), (0.5, 0.0), (0.9, 0.0)])
    for t in TIMES:
        g = group(result, "over r", t=t)
        # equal distributions: the distance is the noise floor, within 4 jackknife errors
        assert abs(g["distance"] - g["noise_floor"]) < 4 * g["error"], g
    for p in result["pairs"]:
        # 80 bins at most, independent draws: chi2/dof within 5 sigma of 1 (sigma = sqrt(2/dof))
        assert abs(p["chi2"] / p["dof"] - 1) < 5 * math.sqrt(2 / p["dof"]), p


def test_a_shifted_distribution_is_far_above_the_floor(tmp_path):
    result = sweep(tmp_path, [(0.0, 0.0), (0.5, 0.0), (0.9, 0.1)])  # a shift of 0.22 standard deviations
    for t in TIMES:
        g = group(result, "over r", t=t)
        assert g["distance"] > g["noise_floor"] + 5 * g["error"], g
    same = [p for p in result["pairs"] if p["r_b"] == 0.5]
    shifted = [p for p in result["pairs"] if p["r_b"] == 0.9]
    assert all(p["distance"] < p["noise_floor"] + 4 * p["error"] for p in same)
    assert all(p["chi2"] > 3 * p["dof"] for p in shifted)


def test_a_group_distance_is_the_mean_l1_distance_of_its_pairs(tmp_path):
    result = sweep(tmp_path, [(0.0, 0.0), (0.9, 0.1)])
    dz = 2 * Z_MAX / BINS
    with h5py.File(tmp_path / "0-r" / "result.h5") as f:
        h = f["particles/realizations/histogram_density"][:].reshape(REALIZATIONS, len(TIMES), BINS)
    mean = h.mean(axis=0)
    expected = np.mean([np.sum(np.abs(mean[a] - mean[b])) * dz for a, b in [(0, 1), (0, 2), (1, 2)]])
    assert group(result, "over t", r=0.0)["distance"] == pytest.approx(expected, rel=1e-12)
    assert result["realizations"] == REALIZATIONS and result["r"] == [0.0, 0.9]
