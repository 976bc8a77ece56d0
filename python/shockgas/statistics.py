"""Shock statistics over realizations: `shockgas stats` from Python (docs/statistics.md)."""
import csv
import math
import os

from . import _shockgas


_DISTRIBUTIONS = ("mass", "velocity", "spacing")


def _number(text):
    return float(text) if text != "" else math.nan


def statistics(dirs, out=None, plots=True):
    """The shock statistics of one gas over every realization the directories hold
    (runs, merged runs, shards; other seeds are more realizations), written to
    `out` (default out/<scene>-stats) as `shockgas stats` writes them, and returned
    as a dict read from its statistics.csv:

        realizations, count (mean clusters of >= 2 particles per realization),
        count_error, count_exact, mass_speed_correlation (+ _error), and for
        "mass", "velocity", "spacing" a dict of edges, value, error, exact (lists)
        and, where a chi-square against the exact law was formed, chi2, dof, p_value.

    Errors are the jackknife over realizations (nan from one). Raises InputError
    (naming the directory) for directories of different gases, a realization held
    twice, or runs that did not record their final clusters."""
    dirs = [os.fspath(d) for d in ([dirs] if isinstance(dirs, (str, os.PathLike)) else dirs)]
    written = _shockgas._statistics(dirs, "" if out is None else os.fspath(out), plots)
    result = {"dir": written}
    for quantity in _DISTRIBUTIONS:
        result[quantity] = {"edges": [], "value": [], "error": [], "exact": []}
    with open(os.path.join(written, "statistics.csv"), newline="") as f:
        for row in csv.DictReader(f):
            name, value = row["quantity"], _number(row["value"])
            if row["bin_low"] != "":
                d = result[name]
                if not d["edges"]:
                    d["edges"].append(_number(row["bin_low"]))
                d["edges"].append(_number(row["bin_high"]))
                d["value"].append(value)
                d["error"].append(_number(row["error"]))
                d["exact"].append(_number(row["exact"]))
            elif name.split("_", 1)[0] in _DISTRIBUTIONS and name != "mass_speed_correlation":
                quantity, key = name.split("_", 1)
                result[quantity][key] = int(value) if key == "dof" else value
            else:
                result[name] = value
                if row["error"] != "" or name in ("count", "mass_speed_correlation"):
                    result[name + "_error"] = _number(row["error"])
                if row["exact"] != "":
                    result[name + "_exact"] = _number(row["exact"])
    result["realizations"] = int(result["realizations"])
    return result
