"""Files another program wrote or rewrote, read by `shockgas info` and by
shockgas.load: an HDF5 file not written by shockgas is no result file, and a
result rewritten without what its layout carries (its own checksum in its
first 512 bytes since layout 2.0, /@attributes_sha256 since 3.1) is damaged:
exit 2 and an InputError, never read as sound. Found from outside: h5py's
copy of a result with one value changed, and a plain h5py file claiming
layout 4.0, were read with exit 0 (as layout 1.0 files, whose integrity
cannot be checked)."""

import hashlib
import shutil
import subprocess

import h5py
import numpy as np
import pytest

import shockgas
from conftest import BUILD_DIR

SCENE = """
[scene]
name = "rewritten"
[initial]
N = 500
seed = 2
[particles]
r = 0.5
t_end = 20
samples = 5
[output]
plots = false
"""


def info(path):
    """`shockgas info PATH`: exit code and standard error."""
    done = subprocess.run([str(BUILD_DIR / "shockgas"), "info", str(path)], capture_output=True, text=True)
    return done.returncode, done.stderr


def refused(path, problem):
    """Both readers refuse the file, naming the problem."""
    code, err = info(path)
    assert code == 2, err
    assert problem in err, err
    with pytest.raises(shockgas.InputError, match=problem):
        shockgas.load(path)


def write_own_checksum(path):
    """The block shockgas writes in the first 512 bytes: the SHA-256 of the rest and its size."""
    with open(path, "r+b") as f:
        rest = f.read()[512:]
        line = f"shockgas sha256 {hashlib.sha256(rest).hexdigest()} {len(rest)}\n".encode()
        f.seek(0)
        f.write(line + bytes(512 - len(line)))


@pytest.fixture(scope="module")
def result(tmp_path_factory, command):
    tmp = tmp_path_factory.mktemp("rewritten")
    (tmp / "scene.toml").write_text(SCENE)
    command("run", tmp / "scene.toml", "--out", tmp / "out", "--quiet", "--no-plots")
    return tmp / "out" / "result.h5"


def alone(result, tmp_path, name):
    """A copy of the result alone in a directory (no manifest beside it)."""
    copy = tmp_path / name
    shutil.copyfile(result, copy)
    return copy


def test_the_result_alone_is_read_as_sound(result, tmp_path):
    code, err = info(alone(result, tmp_path, "sound.h5"))
    assert code == 0, err


def test_an_hdf5_file_not_written_by_shockgas_is_no_result(tmp_path):
    for name, attrs in (("plain.h5", {}), ("claims.h5", {"layout_version": "4.0"})):
        with h5py.File(tmp_path / name, "w") as f:
            f["x"] = np.arange(10.0)
            f.attrs.update(attrs)
        refused(tmp_path / name, "not a result file")


def test_a_result_rewritten_by_another_program_is_damaged(result, tmp_path):
    """Every object and attribute copied by h5py into a new file (no user block), one value changed."""
    copy = tmp_path / "copied.h5"
    with h5py.File(result, "r") as src, h5py.File(copy, "w") as dst:
        for name in src:
            src.copy(src[name], dst, name=name)
        dst.attrs.update(src.attrs)
        T = dst["particles/T"]
        T[0] = T[0] * 1.5
    code, err = info(copy)
    assert code == 2 and "hold no checksum of the file" in err and "layout 4.0" in err, err
    refused(copy, "hold no checksum of the file")


def test_a_result_without_its_attributes_digest_is_damaged(result, tmp_path):
    """/@attributes_sha256 deleted and the file's own checksum taken again: its absence
    would pass for a file of layout 3.0 or before, which this one says it is not."""
    copy = alone(result, tmp_path, "undigested.h5")
    with h5py.File(copy, "r+") as f:
        del f.attrs["attributes_sha256"]
        f.attrs["scene_name"] = "tampered"
    write_own_checksum(copy)
    refused(copy, "it has no /@attributes_sha256")


def test_a_damaged_signature_behind_the_checksum_block_is_damage(result, tmp_path):
    """The HDF5 signature at byte 512 overwritten: a damaged result, not 'not an HDF5 file'."""
    copy = alone(result, tmp_path, "signature.h5")
    with open(copy, "r+b") as f:
        f.seek(513)
        f.write(b"X")
    refused(copy, "damaged")
    assert "not an HDF5 file" not in info(copy)[1]
