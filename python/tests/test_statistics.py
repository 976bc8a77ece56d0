"""shockgas.statistics: the command's statistics from Python, the same numbers in
the same files, and its refusals as InputError."""

import math

import pytest

import shockgas

SCENE = {"initial": {"N": 4000, "velocities": "uniform", "seed": 2},
         "particles": {"r": 0, "solver": "hull", "t_end": 300, "samples": 2, "realizations": 6}}


def test_statistics_of_a_run_are_the_commands(tmp_path, command):
    shockgas.run(SCENE, out=tmp_path / "run", plots=False)
    s = shockgas.statistics(tmp_path / "run", out=tmp_path / "py", plots=False)
    command("stats", tmp_path / "run", "--out", tmp_path / "cli", "--no-plots", "-q")
    assert (tmp_path / "py" / "statistics.csv").read_text() == (tmp_path / "cli" / "statistics.csv").read_text()
    assert s["realizations"] == 6
    assert len(s["mass"]["edges"]) == len(s["mass"]["value"]) + 1
    assert s["mass"]["dof"] >= 2 and 0 <= s["mass"]["p_value"] <= 1
    # The mean count and its jackknife error (s / sqrt(R)) against the exact expectation.
    assert s["count_error"] > 0 and s["count_exact"] > 0
    assert math.isfinite(s["mass_speed_correlation"])


def test_a_realization_given_twice_is_an_input_error(tmp_path):
    shockgas.run(SCENE, out=tmp_path / "run", plots=False)
    with pytest.raises(shockgas.InputError, match="both hold realization 0"):
        shockgas.statistics([tmp_path / "run", tmp_path / "run"], out=tmp_path / "twice", plots=False)
    assert not (tmp_path / "twice").exists()
