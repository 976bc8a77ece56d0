"""The engine and the exact hull on numpy arrays."""

import doctest

import numpy as np
import pytest

import shockgas
from conftest import assert_same_bits


def aggregation(geometry, t):
    """The engine at r = 0 (every collision a merge) from 4000 random bodies,
    and the exact hull from the same bodies."""
    b = shockgas.particles.initial_bodies(N=4000, seed=11, remove_mean=geometry == "ring")
    run = shockgas.particles.simulate(b.x, b.v, r=0.0, delta=0.0, geometry=geometry, t_end=t,
                                      samples=1, clusters=False)
    assert run.stop["reason"] == "completed"
    return run.final, shockgas.hull(b.x, b.v, b.m, t, geometry=geometry)


@pytest.mark.parametrize("geometry", ["line", "ring"])
@pytest.mark.parametrize("t", [3.0, 300.0])
def test_the_hull_on_arrays_equals_the_engine_at_r0(geometry, t):
    engine, exact = aggregation(geometry, t)
    L = 4000.0
    assert len(engine.m) == len(exact.m) < 4000  # clusters formed
    # A ring's cluster at the seam may sit at either end in one of the two: align by mass.
    shift = 0
    if geometry == "ring":
        shift = next(s for s in (0, 1, len(engine.m) - 1) if engine.m[s] == exact.m[0])
    e = np.roll(np.arange(len(engine.m)), -shift)
    # The partition: integer masses, exactly; each cluster's members, counted.
    np.testing.assert_array_equal(engine.m[e], exact.m)
    np.testing.assert_array_equal(exact.count, exact.m)
    assert exact.count.sum() == 4000
    # Positions and velocities to rounding: x + v t summed over the merges of a
    # cluster (measured <= 1e-15 L in the library's own test, HullAgreement);
    # 1e-12 L still fails on any wrong merge, which moves x by O(1).
    dx = np.abs(engine.x[e] - exact.x)
    if geometry == "ring":
        dx = np.minimum(dx, L - dx)
    assert dx.max() < 1e-12 * L
    np.testing.assert_allclose(engine.v[e], exact.v, rtol=0, atol=1e-14)


def test_simulate_on_a_scenes_bodies_gives_the_scenes_series():
    scene = {"initial": {"N": 2000, "seed": 5}, "particles": {"r": 0.7, "t_end": 200.0, "samples": 15}}
    r = shockgas.run(scene)
    d = r.datasets
    run = shockgas.particles.simulate(d["/initial/x"], d["/initial/v"], d["/initial/m"], r=0.7,
                                      t_end=200.0, samples=15)
    for name in ("t", "T", "mean_v", "n_clusters", "collisions", "dissipated"):
        assert_same_bits(run[name], d["/particles/" + name], name)
    for name in "xvm":
        assert_same_bits(run.final[name], d["/particles/final/" + name], name)


def test_the_callers_arrays_are_left_alone():
    b = shockgas.particles.initial_bodies(N=1000, seed=2)
    x, v = b.x.copy(), b.v.copy()
    shockgas.particles.simulate(x, v, r=0.0, t_end=50.0)
    shockgas.hull(x, v, None, 50.0)
    assert_same_bits(x, b.x, "x")
    assert_same_bits(v, b.v, "v")


def test_records_snapshots_histogram_spacetime():
    b = shockgas.particles.initial_bodies(N=1000, seed=4)
    run = shockgas.particles.simulate(b.x, b.v, r=0.5, t_end=100.0, samples=10, snapshots=[1.0, 10.0],
                                      histogram_bins=8, spacetime=True, spacetime_frames=5)
    assert [s.t for s in run.snapshots] == [1.0, 10.0]
    assert run.snapshots[1].x.shape == run.snapshots[1].m.shape
    assert run.histogram["density"].shape == (len(run.histogram["t"]), 8)
    assert run.spacetime["x"].shape == (5, 1000)
    assert run.T.flags.owndata is False and run.T.base is not None  # the engine's own vector, not a copy
    # at most spacetime_particles world lines, evenly spaced: the whole record's columns at their labels
    few = shockgas.particles.simulate(b.x, b.v, r=0.5, t_end=100.0, samples=10, snapshots=[1.0, 10.0],
                                      histogram_bins=8, spacetime=True, spacetime_frames=5, spacetime_particles=4)
    assert few.spacetime["label"].tolist() == [0, 333, 666, 999]
    assert few.spacetime["label"].dtype == np.int64
    assert_same_bits(few.spacetime["x"], run.spacetime["x"][:, few.spacetime["label"]], "spacetime x")


def test_help_lists_every_key_with_its_unit_and_the_hull_example_runs():
    doc = shockgas.particles.simulate.__doc__
    for key in shockgas.scene_keys():
        if key["table"] == "particles":
            assert f"\n    {key['key']} : {key['kind']}" in doc, key["key"]
    assert "delta : number [length/time], default 0.01" in doc
    assert "E, Rykov & Sinai 1996" in shockgas.hull.__doc__ and "[length/time]" in shockgas.hull.__doc__
    runner = doctest.DocTestRunner()
    for test in doctest.DocTestFinder().find(shockgas.hull, "hull", globs={}):
        runner.run(test)
    assert runner.tries == 3 and runner.failures == 0


def test_unit_masses_by_default_and_the_ring_length():
    x = np.array([0.5, 1.5, 2.5])
    v = np.array([1.0, 0.0, -1.0])
    c = shockgas.hull(x, v, t=2.0, geometry="line")
    assert (c.m.tolist(), c.x.tolist(), c.v.tolist()) == ([3.0], [1.5], [0.0])
    # On a ring of length 10 the outer bodies are 8 apart across the seam and never meet there.
    ring = shockgas.hull(x, v, t=2.0, L=10.0)
    assert ring.m.tolist() == [3.0]


@pytest.mark.filterwarnings("ignore::PendingDeprecationWarning")  # np.matrix, on purpose
def test_numpy_values_of_keywords_are_read_as_the_python_ones():
    # found: a numpy array or numpy bool was read as an integer (r = [0.5] became 0: every collision
    # merged), a float array of snapshots as integers, an int beyond int64 was a RuntimeError
    x, v = np.array([0.5, 1.5]), np.array([1.0, -1.0])
    plain = shockgas.particles.simulate(x, v, r=0.5, t_end=1.0, snapshots=[0.25, 0.5], spacetime=True)
    numpy = shockgas.particles.simulate(x, v, r=np.float64(0.5), t_end=np.array(1.0),
                                       snapshots=np.array([0.25, 0.5]), spacetime=np.bool_(True))
    np.testing.assert_array_equal(numpy.final.v, plain.final.v)
    np.testing.assert_array_equal(numpy.final.v, [-0.5, 0.5])  # r = 0.5 maps g = 2 to -1
    assert [s.t for s in numpy.snapshots] == [0.25, 0.5]
    assert numpy.spacetime is not None
    for bad in (np.array([0.5]), np.array([[0.5]]), np.matrix([[0.5]])):  # np.matrix: a crash (review)
        with pytest.raises(shockgas.InputError, match="particles.r"):
            shockgas.particles.simulate(x, v, r=bad)
    with pytest.raises(shockgas.InputError, match="particles.samples"):
        shockgas.particles.simulate(x, v, samples=2**63)
    scene = {"initial": {"N": 64}, "particles": {"t_end": 10.0, "snapshots": np.array([2.5])}}
    assert shockgas.run(scene).attributes["/particles/snapshots/0@t"] == 2.5


def test_ring_length_zero_means_the_number_of_bodies_as_in_the_library():
    # The one rule of initial.L (ring_length in the library, whose own test is
    # Engine.RingLengthZeroMeansTheNumberOfBodies): L = 0 is L = N, to the bit.
    b = shockgas.particles.initial_bodies(N=300, seed=4)
    keys = dict(r=0.5, t_end=10.0, samples=2)
    zero = shockgas.particles.simulate(b.x, b.v, L=0.0, **keys)
    n = shockgas.particles.simulate(b.x, b.v, L=300.0, **keys)
    default = shockgas.particles.simulate(b.x, b.v, **keys)
    for run in (n, default):
        np.testing.assert_array_equal(zero.final.x, run.final.x)
        np.testing.assert_array_equal(zero.final.v, run.final.v)
