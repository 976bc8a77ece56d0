"""shockgas.load(DIR).to_xarray(): the fields and series of a run as an
xarray.Dataset, compared with the raw arrays of result.h5 read by h5py."""

import os

import h5py
import numpy as np
import pytest

import shockgas

xarray = pytest.importorskip("xarray", reason="python3-xarray is not installed (Debian: apt install python3-xarray)")

SCENE = """
[scene]
name = "xarray"
[initial]
N = 1000
seed = 3
[particles]
r = 0.5
t_end = 100
samples = 12
[continuum]
solvers = ["hopf_lax", "godunov", "pressureless"]
cells = 256
[compare]
[output]
plots = false
"""


def text(value):
    return value.decode() if isinstance(value, bytes) else value


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory, command):
    tmp = tmp_path_factory.mktemp("xarray")
    (tmp / "scene.toml").write_text(SCENE)
    command("run", tmp / "scene.toml", "--out", tmp / "out", "--quiet", "--no-plots")
    return tmp / "out"


def test_the_dataset_holds_the_raw_arrays_on_their_coordinates(run_dir):
    ds = shockgas.load(run_dir).to_xarray()
    assert set(ds.coords) >= {"x", "t", "solver"}
    assert list(ds["solver"].values) == ["godunov", "hopf_lax", "pressureless"]
    with h5py.File(run_dir / "result.h5", "r") as f:
        np.testing.assert_array_equal(ds["x"].values, f["continuum/godunov/x"][()])
        np.testing.assert_array_equal(ds["t"].values, f["particles/t"][()])
        for solver in ds["solver"].values:
            np.testing.assert_array_equal(ds["v"].sel(solver=solver).values, f[f"continuum/{solver}/v"][()])
            assert np.array_equal(f[f"continuum/{solver}/x"][()], ds["x"].values)
        np.testing.assert_array_equal(ds["rho"].sel(solver="pressureless").values,
                                      f["continuum/pressureless/rho"][()])
        np.testing.assert_array_equal(ds["T"].values, f["particles/T"][()])
        np.testing.assert_array_equal(ds["T_stderr"].values, f["particles/T_stderr"][()])
        np.testing.assert_array_equal(ds["count"].values, f["particles/count"][()])
        assert ds["count"].dtype == np.int64
        assert ds["T"].attrs["unit"] == text(f["particles/T"].attrs["unit"]) == "length^2/time^2"
        assert ds["v"].attrs["unit"] == "length/time" and ds["x"].attrs["unit"] == "length"
        assert ds["t"].attrs["unit"] == "time"
        for name in ds.variables:  # every coordinate and variable, as the module's docstring says
            assert "unit" in ds[name].attrs, name


def test_the_scene_and_layout_are_in_the_attributes(run_dir):
    ds = shockgas.load(run_dir).to_xarray()
    assert ds.attrs["scene_name"] == "xarray"
    assert ds.attrs["scene_text"].strip() == SCENE.strip()
    with h5py.File(os.path.join(run_dir, "result.h5"), "r") as f:
        assert ds.attrs["layout_version"] == f.attrs["layout_version"]
    major, minor = ds.attrs["layout_version"].split(".")
    assert int(major) >= 4 and int(minor) >= 0
    assert "[particles]" in ds.attrs["resolved_parameters"] and "r = 0.5" in ds.attrs["resolved_parameters"]


def test_the_fields_say_their_own_time(run_dir):
    """v and rho are at t_end, which the coordinate t (the particles' samples) does not say."""
    ds = shockgas.load(run_dir).to_xarray()
    with h5py.File(run_dir / "result.h5", "r") as f:
        t_end = float(f["continuum/godunov"].attrs["t"])
    for field in ("v", "rho"):
        assert ds[field].attrs["t_end"] == t_end
        assert "at t_end" in ds[field].attrs["description"], ds[field].attrs["description"]


def test_a_directory_of_layout_1_says_so():
    """A file without /@layout_version is of layout 1.0 (docs/output.md); the Dataset says it."""
    from conftest import SOURCE_DIR

    ds = shockgas.load(SOURCE_DIR / "tests" / "data" / "layout-1.0").to_xarray()
    assert ds.attrs["layout_version"] == "1.0"
