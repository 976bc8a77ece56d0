"""Scenes from Python against the command: the same datasets, bit for bit."""

import os
import tomllib
import warnings

import h5py
import numpy as np
import pytest

import shockgas
from conftest import SOURCE_DIR, assert_same_bits

# Every part of a run, small: an ensemble with snapshots, histogram and
# space-time record, four solvers, the comparison, the animation's frames.
SCENE = """
[scene]
name = "pytest"
[initial]
N = 3000
seed = 7
[particles]
r = 0.5
delta = 1e-2
t_end = 300
realizations = 2
samples = 20
snapshots = [10, 100]
histogram_bins = 16
spacetime = true
spacetime_frames = 20
[continuum]
solvers = ["hopf_lax", "godunov", "godunov2", "pressureless"]
cells = 512
[compare]
[output]
plots = false
animation = true
animation_frames = 4
"""


def read_h5(path):
    """Every dataset and attribute of a result file, read by h5py (not by shockgas)."""
    datasets, attributes = {}, {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                datasets["/" + name] = obj[()]
            else:
                for key, value in obj.attrs.items():
                    attributes[f"/{name}@{key}"] = value.decode() if isinstance(value, bytes) else value
        for key, value in f.attrs.items():
            attributes[f"/@{key}"] = value.decode() if isinstance(value, bytes) else value
        f.visititems(visit)
    return datasets, attributes


def timing(name):
    return "wall_seconds" in name or "per_second" in name


@pytest.fixture(scope="module")
def command_result(tmp_path_factory, command):
    tmp = tmp_path_factory.mktemp("command")
    (tmp / "scene.toml").write_text(SCENE)
    command("run", tmp / "scene.toml", "--out", tmp / "out", "--quiet", "--no-plots")
    return tmp / "out"


@pytest.fixture(scope="module")
def dict_result():
    return shockgas.run(tomllib.loads(SCENE))


def test_a_dict_scene_gives_every_dataset_of_the_command_bit_for_bit(command_result, dict_result):
    datasets, _ = read_h5(command_result / "result.h5")
    assert "/particles/snapshots/1/x" in datasets and "/particles/spacetime/x" in datasets
    assert "/continuum/pressureless/rho" in datasets and "/compare/shocks_x" in datasets
    assert any(name.startswith("/animation/") for name in datasets)
    assert sorted(dict_result.datasets) == sorted(datasets)
    for name, values in datasets.items():
        assert_same_bits(dict_result.datasets[name], values, name)


def test_a_dict_scene_gives_the_commands_attributes_and_figures(command_result, dict_result):
    _, attributes = read_h5(command_result / "result.h5")
    attributes.pop("/@attributes_sha256")  # the file's digest of its attributes (h5py reads it; load does not)
    differ = {"/@created_utc", "/@scene_path", "/@scene_text"}  # when, and how the scene was given
    assert sorted(dict_result.attributes) == sorted(attributes)
    for name, value in attributes.items():
        if name not in differ and not timing(name):
            assert dict_result.attributes[name] == value, name
    from_file = shockgas.load(command_result)
    assert sorted(from_file.figures) == sorted(dict_result.figures)
    for key, value in from_file.figures.items():
        if not timing(key):
            assert dict_result.figures[key] == value, key


def test_load_returns_the_object_run_returned(tmp_path):
    scene = tomllib.loads(SCENE)
    ran = shockgas.run(scene, out=tmp_path / "run", plots=False)
    assert ran.directory == str(tmp_path / "run")
    assert sorted(os.listdir(tmp_path / "run")) == [
        "manifest.json", "report.html", "report.md", "result.h5", "result.xdmf", "summary.json"]
    loaded = shockgas.load(tmp_path / "run" / "result.h5")
    assert sorted(loaded.datasets) == sorted(ran.datasets)
    for name in ran.datasets:
        assert_same_bits(loaded.datasets[name], ran.datasets[name], name)
        assert loaded.units[name] == ran.units[name]
    assert sorted(loaded.attributes) == sorted(ran.attributes)
    for name, value in ran.attributes.items():
        if name != "/@created_utc":  # taken once for the file and once for memory
            assert loaded.attributes[name] == value, name
    assert loaded.summary == ran.summary


def test_a_result_looks_up_datasets_attributes_and_figures(dict_result):
    assert dict_result["/particles/T"] is dict_result.datasets["/particles/T"]
    assert dict_result["/particles@stop_reason"] == "completed"
    assert dict_result["particles.r"] == 0.5
    assert dict_result.units["/particles/T"] == "length^2/time^2"
    assert dict_result.datasets["/particles/histogram/density"].shape == (20, 16)
    with pytest.raises(KeyError):
        dict_result["/particles/nothing"]


def test_overrides_and_toml_text_run_the_same_scene(dict_result):
    text = SCENE.replace("r = 0.5", "r = 0.9")
    by_text = shockgas.run_toml(text, overrides={"particles.r": 0.5, "continuum.solvers": ["hopf_lax"]})
    assert by_text.attributes["/@overrides"] == "--set particles.r=0.5 --set continuum.solvers=['hopf_lax']"
    assert_same_bits(by_text.datasets["/particles/T"], dict_result.datasets["/particles/T"], "/particles/T")
    assert "/continuum/godunov/v" not in by_text.datasets


def test_a_scene_file_runs_with_overrides():
    r = shockgas.run(SOURCE_DIR / "data" / "scenes" / "riemann.toml", overrides={"continuum.cells": 64})
    assert r.figures["continuum.godunov.cells"] == 64
    assert r.attributes["/@scene_name"] == "riemann"


def test_a_sweep_runs_into_its_directory(tmp_path):
    scene = {
        "initial": {"N": 500},
        "particles": {"t_end": 100.0, "samples": 10},
        "sweep": {"variants": ["particles.r=0.5", "particles.r=0.9"], "labels": ["r=0.5", "r=0.9"]},
    }
    with pytest.raises(ValueError) as e:
        shockgas.run(scene)
    assert e.value.key == "sweep"
    r = shockgas.run(scene, out=tmp_path / "sweep", plots=False)
    assert r.attributes["/sweep/1@label"] == "r=0.9"
    assert r.datasets["/sweep/0/particles/T"].shape == r.datasets["/sweep/1/particles/T"].shape
    variant = shockgas.load(tmp_path / "sweep" / "1-r_0.9")
    assert_same_bits(variant.datasets["/particles/T"], r.datasets["/sweep/1/particles/T"], "T")
    assert np.all(np.isfinite(variant.datasets["/particles/T"]))


def test_the_auto_solver_choice_is_noted_as_the_command_notes_it(command, tmp_path):
    scene = {"initial": {"N": 200, "seed": 3}, "particles": {"r": 0.5, "solver": "auto", "t_end": 5, "samples": 2}}
    with pytest.warns(shockgas.SolverNote, match=r'particles.solver = "auto": the event engine') as caught:
        r = shockgas.run(scene, plots=False)
    assert r.notes == [str(w.message) for w in caught]
    # the same words as `shockgas run`'s "shockgas: note: ..."
    path = tmp_path / "scene.toml"
    path.write_text("[initial]\nN = 200\nseed = 3\n[particles]\nr = 0.5\nsolver = 'auto'\nt_end = 5\nsamples = 2\n")
    cli = command("run", path, "--out", tmp_path / "out", "--no-plots", "-q")
    assert f"shockgas: note: {r.notes[0]}" in cli.stderr
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert shockgas.run({**scene, "particles": {**scene["particles"], "solver": "events"}}, plots=False).notes == []
