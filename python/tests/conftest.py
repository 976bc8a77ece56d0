"""Shared fixtures: where the build and the sources are, and small scenes."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]
BUILD_DIR = pathlib.Path(os.environ.get("SHOCKGAS_BUILD_DIR", SOURCE_DIR / "build"))


@pytest.fixture(scope="session")
def command():
    """Runs the `shockgas` command of the build; returns its completed process."""
    exe = BUILD_DIR / "shockgas"
    if not exe.exists():
        pytest.skip(f"{exe} not built")

    def run(*args):
        return subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True, check=True)

    return run


def python_env():
    """The environment of a child Python that imports this build's module."""
    env = dict(os.environ)
    env["PYTHONPATH"] = str(BUILD_DIR / "python") + os.pathsep + env.get("PYTHONPATH", "")
    return env


def bits(a):
    """An array's bytes as unsigned integers: equal bits, not only equal values."""
    a = np.ascontiguousarray(a)
    return a.view(np.uint8)


def assert_same_bits(a, b, name):
    assert a.shape == b.shape, f"{name}: shape {a.shape} != {b.shape}"
    assert a.dtype == b.dtype, f"{name}: dtype {a.dtype} != {b.dtype}"
    assert np.array_equal(bits(a), bits(b)), f"{name}: values differ (max |a - b| = {np.max(np.abs(a - b))})"
