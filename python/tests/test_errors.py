"""Bad input is a ValueError naming the key, with the command line's message;
a failed run is a RuntimeError."""

import numpy as np
import pytest

import shockgas

X = np.arange(100) + 0.5
V = np.linspace(-1, 1, 100)


def raises_input_error(call, key):
    with pytest.raises(ValueError) as e:
        call()
    assert isinstance(e.value, shockgas.InputError)
    assert e.value.key == key
    assert key in str(e.value) and "is not allowed; allowed:" in str(e.value)
    return e.value


def test_a_keyword_out_of_range_names_the_scene_key():
    e = raises_input_error(lambda: shockgas.particles.simulate(X, V, r=2.0), "particles.r")
    assert str(e) == "particles.r = 2 is not allowed; allowed: a finite number in [0, 1]"
    raises_input_error(lambda: shockgas.particles.simulate(X, V, geometry="torus"), "particles.geometry")
    raises_input_error(lambda: shockgas.particles.simulate(X, V, samples=0), "particles.samples")
    raises_input_error(lambda: shockgas.particles.simulate(X, V, r=0.5, solver="hull"), "particles.solver")
    raises_input_error(lambda: shockgas.particles.simulate(X, V, L=-1.0), "initial.L")
    raises_input_error(lambda: shockgas.particles.simulate(X, V, realizations=4), "particles.realizations")
    raises_input_error(lambda: shockgas.continuum.solve("godunov", V, dx=0.01, cfl=2.0), "continuum.cfl")
    raises_input_error(lambda: shockgas.particles.ensemble(N=0), "initial.N")


def test_an_unknown_keyword_is_named_with_the_accepted_ones():
    e = raises_input_error(lambda: shockgas.particles.simulate(X, V, rr=0.5), "rr")
    assert "r, delta, subthreshold" in e.allowed
    e = raises_input_error(lambda: shockgas.particles.ensemble(NN=10), "NN")
    assert e.allowed.startswith("a keyword of shockgas.particles.ensemble: N, positions")
    assert e.allowed.count("solver") == 1  # [particles] and [compare] both declare it: the first's


def test_an_unknown_solver_lists_the_registered_ones():
    e = raises_input_error(lambda: shockgas.continuum.solve("rusanov", V, dx=0.01), "continuum.solvers")
    for s in shockgas.continuum.solvers():
        assert s["name"] in e.allowed


def test_bad_arrays_name_their_argument():
    raises_input_error(lambda: shockgas.particles.simulate(X, V[:-1]), "v")
    raises_input_error(lambda: shockgas.particles.simulate(X[::-1].copy(), V), "initial.bodies.x[1]")
    bad_v = V.copy()
    bad_v[3] = np.nan  # named by itself, not by the position beside it
    e = raises_input_error(lambda: shockgas.particles.simulate(X, bad_v), "initial.bodies.v[3]")
    assert str(e).startswith("initial.bodies.v[3] = nan is not allowed")
    raises_input_error(lambda: shockgas.hull(X, V, -np.ones(100), 1.0), "bodies.m")
    raises_input_error(lambda: shockgas.hull(X, V, None, -1.0), "t")
    raises_input_error(lambda: shockgas.hull(np.ones((2, 50)), V, None, 1.0), "x")
    raises_input_error(lambda: shockgas.continuum.solve("godunov", V, t_end=0.1), "dx")


def test_an_argument_the_form_of_the_data_does_not_use_is_refused():
    # found: domain and L with cell values, m without x, rho0 with x and dx with
    # expressions were ignored without a word
    solve = shockgas.continuum.solve
    raises_input_error(lambda: solve("godunov", V, dx=0.01, domain=2.0), "domain")
    raises_input_error(lambda: solve("godunov", V, dx=0.01, L=3.0), "L")
    raises_input_error(lambda: solve("godunov", V, dx=0.01, m=np.ones(100)), "m")
    raises_input_error(lambda: solve("godunov", "0.5 + sin(2*pi*x)", dx=0.01), "dx")
    raises_input_error(lambda: solve("godunov", "0.5 + sin(2*pi*x)", L=2.0), "L")
    raises_input_error(lambda: solve("godunov", V, rho0=np.ones(100), x=X), "rho0")
    raises_input_error(lambda: solve("godunov", V, x=X, dx=1.0), "dx")
    raises_input_error(lambda: solve("godunov", V, x=X, domain=100.0), "domain")
    assert solve("godunov", V, x=X, L=100.0, t_end=0.1, cells=50).t == 0.1  # what each form uses still runs


def test_a_dict_scene_error_says_where_in_the_dict():
    e = raises_input_error(lambda: shockgas.run({"particles": {"r": 2}}), "particles.r")
    assert e.where == "scene['particles']['r']"
    assert str(e) == "scene['particles']['r']: particles.r = 2 is not allowed; allowed: a finite number in [0, 1]"
    e = raises_input_error(lambda: shockgas.run({"particles": {}}, overrides={"particles.delta": -1}),
                           "particles.delta")
    assert e.where == "overrides['particles.delta']"
    raises_input_error(lambda: shockgas.run({"particles": {"r": None}}), "particles.r")
    raises_input_error(lambda: shockgas.run({"particles": 3}), "particles")
    e = raises_input_error(lambda: shockgas.run_toml("[particles]\nt_end = 10\nr = 7\n"), "particles.r")
    assert e.where == "<toml>:3"
    with pytest.raises(shockgas.InputError) as empty:  # the scene as a whole, not a key of it
        shockgas.run({})
    assert str(empty.value) == "scene: runs nothing: a scene needs [particles] or [continuum]"


def test_a_scene_file_error_says_file_and_line(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text("[initial]\nN = 100\n[particles]\ndelta = -1\n")
    e = raises_input_error(lambda: shockgas.run(path), "particles.delta")
    assert e.where == f"{path}:4"
    assert not (tmp_path / "out").exists()


def test_a_run_that_fails_is_a_runtime_error():
    # Beyond the scheme's stable range on purpose: the speeds blow up and the
    # time step stops advancing; a failure, never a result.
    with pytest.raises(RuntimeError, match="blown up"):
        shockgas.continuum.solve("godunov", "sin(2*pi*x)", cells=64, t_end=5.0, cfl=50.0,
                                 allow_unstable=True)


def test_deposit_refuses_bodies_it_cannot_deposit():
    # found: a NaN position spread NaN over two cells, a negative mass gave negative densities
    one = np.array([0.5])
    raises_input_error(lambda: shockgas.compare.deposit(np.array([np.nan]), one, length=1.0, cells=4),
                       "compare.bodies.x[0]")
    raises_input_error(lambda: shockgas.compare.deposit(one, np.array([np.inf]), length=1.0, cells=4),
                       "compare.bodies.v[0]")
    raises_input_error(lambda: shockgas.compare.deposit(np.array([0.1, 0.6]), np.ones(2), m=np.array([1.0, -1.0]),
                                                        length=1.0, cells=4), "compare.bodies.m[1]")


def test_a_negative_count_is_an_input_error_naming_it():
    # found: a negative int failed pybind's conversion to an unsigned count with a raw TypeError
    v = np.sin(2 * np.pi * (np.arange(64) + 0.5) / 64)
    raises_input_error(lambda: shockgas.compare.deposit(X, V, length=100.0, cells=-3), "compare.cells")
    raises_input_error(lambda: shockgas.compare.detect_shocks(v, 1.0, max_width_cells=-2),
                       "compare.max_width_cells")
    raises_input_error(lambda: shockgas.compare.sawtooth(v, 1.0, 0.5, [0.5], skip_cells=-1),
                       "compare.sawtooth.skip_cells")
    raises_input_error(lambda: shockgas.compare.sawtooth(v, 1.0, 0.5, [0.5], min_cells=-1),
                       "compare.sawtooth.min_cells")
    raises_input_error(lambda: shockgas.particles.initial_bodies(-1, N=100), "realization")
    # and so were a bool (taken as 1), a fraction and an int beyond int64; a whole float is a count
    for bad in (True, 2.5, 2**64, "4"):
        raises_input_error(lambda: shockgas.compare.deposit(X, V, length=100.0, cells=bad), "compare.cells")
    raises_input_error(lambda: shockgas.particles.initial_bodies(2**64, N=100), "realization")
    assert shockgas.compare.deposit(X, V, length=100.0, cells=4.0).rho.size == 4
    field = shockgas.continuum.solve("hopf_lax", v, dx=1 / 64, t_end=0.5)
    raises_input_error(lambda: shockgas.compare.snapshot(X / 100, V, None, field, N=-5), "initial.N")


def test_the_comparisons_refuse_values_they_cannot_use():
    # found: NaN densities gave a shock of mass 0, a NaN velocity a NaN slope, negative weights no
    # ramps, a field of 10 values on 256 cells was compared, and a short m was reported as v
    v = np.sin(2 * np.pi * (np.arange(64) + 0.5) / 64)
    raises_input_error(lambda: shockgas.compare.detect_shocks(v, 1.0, np.full(64, np.nan)), "compare.rho")
    raises_input_error(lambda: shockgas.compare.sawtooth(np.r_[np.nan, v[1:]], 1.0, 0.5, [0.5]), "compare.v")
    raises_input_error(lambda: shockgas.compare.sawtooth(v, 1.0, 0.5, [0.5], weights=-np.ones(64)),
                       "compare.weights")
    raises_input_error(lambda: shockgas.compare.sawtooth(v, 0.0, 0.5, [0.25]), "compare.length")
    raises_input_error(lambda: shockgas.compare.deposit(X, V, V[:3], length=100.0, cells=4), "len(m)")
    # found: a NaN position named another body as unsorted; L = 0 and t < 0 named internal keys
    raises_input_error(lambda: shockgas.compare.find_clusters(np.r_[np.nan, X[1:]], V, L=100.0, t=1.0),
                       "cluster.bodies.x[0]")
    raises_input_error(lambda: shockgas.compare.find_clusters(X, V, L=0.0, t=1.0), "L")
    raises_input_error(lambda: shockgas.compare.find_clusters(X, V, L=100.0, t=-1.0), "t")
    field = shockgas.continuum.solve("hopf_lax", v, dx=1 / 64, t_end=0.5)
    field.v = field.v[:10]
    raises_input_error(lambda: shockgas.compare.snapshot(X / 100, V, None, field, N=100), "len(field.v)")


def test_a_call_that_cannot_fit_in_memory_is_refused_before_any_work():
    # found: the kernel's out-of-memory killer ended the Python process (the
    # command refused the same scene); petabytes, beyond any machine
    e = raises_input_error(lambda: shockgas.particles.simulate(X, V, t_end=1.0, histogram_bins=10**12),
                           "particles.histogram_bins")
    assert "a scene that fits in the memory available" in e.allowed
    raises_input_error(lambda: shockgas.continuum.solve("godunov", V, dx=0.01, cells=10**13), "continuum.cells")
    raises_input_error(lambda: shockgas.particles.ensemble(N=10**15, t_end=1.0), "initial.N")
    # the keyword given, not the default it multiplies (particles.samples)
    raises_input_error(lambda: shockgas.particles.ensemble(N=100, t_end=1.0, realizations=10**12),
                       "particles.realizations")
    raises_input_error(lambda: shockgas.compare.deposit(X, V, length=100.0, cells=10**15), "compare.cells")
    raises_input_error(lambda: shockgas.particles.initial_bodies(N=10**15), "initial.N")
