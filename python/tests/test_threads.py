"""Calls from several Python threads at once, and progress on the calling thread."""

import threading
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import shockgas
from conftest import assert_same_bits

B = shockgas.particles.initial_bodies(N=3000, seed=8)


def hopf_cole(cells):  # FFTW plans a transform of its own size in each call
    return shockgas.continuum.solve("hopf_cole", "0.5 + sin(2*pi*x)", cells=cells, t_end=0.3, nu=2e-2,
                                    hopf_cole_path="fft").v


def simulate(r):
    return shockgas.particles.simulate(B.x, B.v, r=r, t_end=300.0, samples=10).T


def scene(r):
    return shockgas.run({"initial": {"N": 1000}, "particles": {"r": r, "t_end": 100.0},
                         "continuum": {"solvers": ["hopf_lax", "hopf_cole"], "cells": 128,
                                       "nu": 5.0}}).datasets["/continuum/hopf_cole/v"]


JOBS = [(hopf_cole, c) for c in (64, 96, 128, 160, 192, 256)] + [(simulate, r) for r in (0.3, 0.6, 0.9)] + \
       [(scene, r) for r in (0.2, 0.8)]


def test_calls_from_several_threads_give_the_results_of_one_thread():
    alone = [f(arg) for f, arg in JOBS]
    for _ in range(3):
        with ThreadPoolExecutor(max_workers=6) as pool:
            together = list(pool.map(lambda job: job[0](job[1]), JOBS))
        for (f, arg), a, b in zip(JOBS, alone, together):
            assert_same_bits(b, a, f"{f.__name__}({arg})")


def test_progress_reaches_the_callback_on_the_calling_thread():
    calls = []

    def progress(stage, fraction, time):
        calls.append((stage, fraction, time, threading.get_ident()))

    shockgas.run({"initial": {"N": 20000}, "particles": {"r": 0.5, "t_end": 3000.0},
                  "continuum": {"solvers": ["hopf_lax", "godunov"], "cells": 2048}}, progress=progress)
    assert {c[3] for c in calls} == {threading.get_ident()}
    stages = [c[0] for c in calls]
    assert stages[0] == "particles" and "continuum/godunov" in stages
    assert all(0.0 <= c[1] <= 1.0 for c in calls)
    particles = [c for c in calls if c[0] == "particles"]
    assert np.all(np.diff([c[2] for c in particles]) >= 0)  # simulated time only goes on


def test_a_progress_bar_or_line_is_shown_when_asked(capsys):
    shockgas.particles.simulate(B.x, B.v, r=0.5, t_end=300.0, progress=False)
    assert capsys.readouterr().err == ""
    shockgas.particles.simulate(B.x, B.v, r=0.5, t_end=300.0, progress=True)
    assert "particles" in capsys.readouterr().err  # tqdm's bar, or the line where tqdm is missing
