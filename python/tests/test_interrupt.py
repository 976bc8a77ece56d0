"""Ctrl-C (SIGINT sent to the process) stops a long run within a second with
KeyboardInterrupt, leaves nothing half-written, and the module works on."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

from conftest import python_env

# A child that starts a run far longer than the test, says when it has begun,
# and reports when KeyboardInterrupt reached it (CLOCK_MONOTONIC: one clock for
# both processes).
CHILD = textwrap.dedent("""
    import os, sys, time
    import shockgas
    kind, out = sys.argv[1], sys.argv[2]
    b = shockgas.particles.initial_bodies(N=200000, seed=1)
    print("started", flush=True)
    try:
        if kind == "simulate":
            shockgas.particles.simulate(b.x, b.v, r=0.5, delta=1e-2, t_end=1e7, samples=5)
        else:
            shockgas.run({"initial": {"N": 200000}, "particles": {"r": 0.5, "t_end": 1e7}}, out=out, plots=False)
        print("finished", flush=True)
    except KeyboardInterrupt:
        print(f"interrupted {time.monotonic()!r}", flush=True)
    print("left", sorted(os.listdir(out)) if os.path.isdir(out) else None, flush=True)
    again = shockgas.particles.simulate(b.x[:1000], b.v[:1000], r=0.5, t_end=10.0, samples=2)
    print("again", again.stop["reason"], flush=True)
""")


def interrupt_child(kind, tmp_path):
    child = subprocess.Popen([sys.executable, "-c", CHILD, kind, str(tmp_path / "out")], env=python_env(),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(1.0)  # well inside the run
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=60)
    finally:
        child.kill()
        child.wait()
    assert child.returncode == 0, err
    lines = out.splitlines()
    assert lines[0].startswith("interrupted"), out + err
    return float(lines[0].split()[1]) - sent, lines[1:]


@pytest.mark.parametrize("kind", ["simulate", "run"])
def test_ctrl_c_raises_keyboard_interrupt_within_a_second(kind, tmp_path):
    delay, rest = interrupt_child(kind, tmp_path)
    assert 0 <= delay < 1.0
    # Nothing half-written: a run's temporary files are removed as it unwinds.
    assert rest[0] in ("left None", "left []"), rest
    # The request is forgotten once the run has stopped: the module runs on.
    assert rest[1] == "again completed"


def test_the_module_installs_no_signal_handler(tmp_path):
    code = textwrap.dedent(f"""
        import signal, numpy as np, shockgas
        before = signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)
        shockgas.particles.simulate(np.arange(100) + 0.5, np.linspace(-1, 1, 100), t_end=10.0)
        shockgas.run({{"initial": {{"N": 100}}, "particles": {{"t_end": 10.0}}}}, out={str(tmp_path / "out")!r},
                     plots=False)
        after = signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)
        print(before[0] is signal.default_int_handler, after == before)
    """)
    out = subprocess.run([sys.executable, "-c", code], env=python_env(), capture_output=True, text=True,
                         check=True)
    assert out.stdout.split() == ["True", "True"]


# SIGTERM (or SIGHUP) to a Python process inside shockgas.run(out=...) left the
# run's staging directory and lock beside out (finding of a hostile pass): the
# run unwinds first, then the process ends by the signal as it was asked to.
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGHUP])
def test_a_terminated_python_run_leaves_nothing_beside_its_output(sig, tmp_path):
    child = subprocess.Popen([sys.executable, "-c", CHILD, "run", str(tmp_path / "out")], env=python_env(),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(1.0)  # well inside the run
        child.send_signal(sig)
        out, err = child.communicate(timeout=60)
    finally:
        child.kill()
        child.wait()
    assert child.returncode == -sig, out + err
    assert sorted(os.listdir(tmp_path)) == [], out + err
