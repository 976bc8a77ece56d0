"""result.xdmf beside result.h5: every data item names a dataset of the file
with its shape and type (always), and ParaView's Python opens it and reads the
values h5py reads (where Debian's python3-paraview is installed)."""

import json
import subprocess
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np
import pytest

SCENE = """
[scene]
name = "xdmf"
[initial]
N = 400
seed = 5
[particles]
r = 0.5
t_end = 40
samples = 8
snapshots = [5]
[continuum]
solvers = ["hopf_lax", "godunov"]
cells = 128
[compare]
[output]
plots = false
animation = true
animation_frames = 3
"""

TYPES = {("Float", "8"): np.float64, ("Float", "4"): np.float32, ("Int", "8"): np.int64}


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory, command):
    tmp = tmp_path_factory.mktemp("xdmf")
    (tmp / "scene.toml").write_text(SCENE)
    command("run", tmp / "scene.toml", "--out", tmp / "out", "--quiet", "--no-plots")
    return tmp / "out"


def test_every_data_item_names_a_dataset_of_its_shape_and_type(run_dir):
    root = ET.parse(run_dir / "result.xdmf").getroot()
    assert root.tag == "Xdmf" and root.get("Version") == "3.0"
    items = [d for d in root.iter("DataItem") if d.get("Format") == "HDF"]
    assert len(items) > 20
    with h5py.File(run_dir / "result.h5", "r") as f:
        for d in items:
            file_name, path = d.text.strip().split(":", 1)
            assert file_name == "result.h5"
            assert path in f, path
            assert tuple(int(n) for n in d.get("Dimensions").split()) == f[path].shape, path
            assert f[path].dtype == TYPES[(d.get("NumberType"), d.get("Precision"))], path
    collections = {g.get("Name"): g for g in root.find("Domain").findall("Grid")}
    assert set(collections) == {"continuum hopf_lax", "continuum godunov", "particles"}
    for name, grid in collections.items():
        assert grid.get("CollectionType") == "Temporal"
        times = [float(g.find("Time").get("Value")) for g in grid.findall("Grid")]
        assert all(a < b for a, b in zip(times, times[1:])), f"{name}: {times}, one grid per time"
    # The frames before t_end (the last of the 3 is at t_end: the fields there stand for it)
    # and the fields at t_end; the initial state, one snapshot and the final one.
    with h5py.File(run_dir / "result.h5", "r") as f:
        frames, t_end = f["animation/t"][()], float(f["continuum/godunov"].attrs["t"])
    assert len(frames) == 3 and frames[-1] == t_end
    grids = collections["continuum godunov"].findall("Grid")
    assert [float(g.find("Time").get("Value")) for g in grids] == [*frames[:-1], t_end]
    assert grids[-1].find("Attribute/DataItem").text.strip() == "result.h5:/continuum/godunov/rho"
    assert len(collections["particles"].findall("Grid")) == 3


PARAVIEW = """
import json, sys
from paraview import simple, servermanager
from vtk.numpy_interface import dataset_adapter as dsa
reader = simple.Xdmf3ReaderS(FileName=[sys.argv[1]])  # an absolute path: the reader finds result.h5 beside it
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
out = {"times": times, "blocks": []}
reader.UpdatePipeline(float(sys.argv[2]))
data = servermanager.Fetch(reader)
it = data.NewIterator()
it.InitTraversal()
while not it.IsDoneWithTraversal():
    block = dsa.WrapDataObject(it.GetCurrentDataObject())
    if block.GetNumberOfPoints() > 0 and "v" in block.PointData.keys():
        out["blocks"].append({"points": block.GetNumberOfPoints(),
                              "v": [float(x) for x in block.PointData["v"]]})
    it.GoToNextItem()
print(json.dumps(out))
"""


def test_paraview_opens_it_and_reads_the_values_h5py_reads(run_dir):
    probe = subprocess.run([sys.executable, "-c", "import paraview.simple"], capture_output=True)
    if probe.returncode != 0:
        pytest.skip("ParaView's Python is not installed (Debian: apt install python3-paraview)")
    # The fields at t_end (/continuum/{solver}): ParaView 5.11's Xdmf3 reader leaves the
    # frames (hyperslabs of /animation/fields) and the particle states empty (docs/output.md).
    with h5py.File(run_dir / "result.h5", "r") as f:
        t_frame = float(f["continuum/godunov"].attrs["t"])
        v_frame = f["continuum/godunov/v"][()]
        v_hopf_lax = f["continuum/hopf_lax/v"][()]
    done = subprocess.run([sys.executable, "-c", PARAVIEW, str((run_dir / "result.xdmf").resolve()), repr(t_frame)],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    answer = json.loads(done.stdout.strip().splitlines()[-1])
    assert any(abs(t - t_frame) <= 1e-12 * max(1.0, t_frame) for t in answer["times"])
    fields = [b for b in answer["blocks"] if b["points"] == v_frame.size]
    # float64, read back exactly by both.
    got = [np.asarray(b["v"], dtype=np.float64) for b in fields]
    assert any(np.array_equal(g, v_frame) for g in got), "godunov's v at t_end not found"
    assert any(np.array_equal(g, v_hopf_lax) for g in got), "hopf_lax's v at t_end not found"
