"""The files of shockgas's runs, read in one place: a run directory (summary.json,
result.h5), the runs kept for docs/paper.md (data/paper-runs/) and the CSV tables
that `shockgas bench`, `shockgas tail` and bench/particles_bench write. Every
script reads them here: summary.json is opened by read_summary alone, a CSV
table by read_csv alone.

A kept run is one directory per particle run (a scene, or one variant of a
sweep), written by scripts/paper/collect_paper_run.py (write_series,
write_histogram below: the format is declared once, both ways):
  summary.json   as the run wrote it;
  T.csv          t, T (ensemble mean), T_stderr, and T_<k> for realization k when
                 the run has at most MAX_REALIZATION_COLUMNS; empty where a
                 sample was not reached;
  histogram.csv  t, z, density (ensemble mean), and when kept density_stderr (the
                 standard error over realizations) and exact (the exact
                 mass-weighted law of the sticky gas averaged over the bin).
Beside the runs of a figure, a comparison of them (collapse*.json, by
scripts/paper/fig4_collapse.py: write_comparison, read_comparison).

Only the standard library at import (tests/tools/check_summary.py runs under
any python3); numpy and h5py are imported by the functions that need them.
"""
import csv
import glob
import json
import math
import os
from collections import defaultdict

SUMMARY = "summary.json"
RESULT = "result.h5"
SERIES = "T.csv"
COMPARISONS = "collapse*.json"  # of the kept runs under one directory
HISTOGRAM = "histogram.csv"
MAX_REALIZATION_COLUMNS = 100

# The units of the kept quantities (docs/output.md): T is a velocity squared.
UNIT_T = "length^2/time^2"
UNIT_T_SCALED = "length^2/time^(4/3)"  # T t^(2/3)


def read_summary(d, first_variant=False, missing=None):
    """A run's summary.json (of run directory d); with first_variant, a sweep's
    first variant's summary. Where d holds none: `missing` when given, else the
    error of the missing file."""
    path = os.path.join(d, SUMMARY)
    if missing is not None and not os.path.exists(path):
        return missing
    with open(path) as f:
        s = json.load(f)
    if first_variant and "analysis" not in s and s.get("variants"):
        s = s["variants"][0]["summary"]
    return s


def open_result(d):
    """The result file of run directory d, open for reading (h5py)."""
    import h5py

    return h5py.File(os.path.join(d, RESULT), "r")


def number(text):
    """A CSV cell as a float; an empty cell (not reached, not applicable) is nan."""
    return float(text) if text not in ("", None) else math.nan


def read_csv(path, numbers=False, missing=None):
    """The rows of a CSV table with a header line, each a dict by column name:
    text cells, or with numbers=True every cell a float (number()). A table that
    does not exist: `missing` when given, else the error of the missing file."""
    if missing is not None and not os.path.exists(path):
        return missing
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [{k: number(v) for k, v in row.items()} for row in rows] if numbers else rows


def run_dirs(root):
    """The kept runs directly under root, by name (none if root is missing)."""
    if not os.path.isdir(root):
        return []
    return [os.path.join(root, d) for d in sorted(os.listdir(root))
            if os.path.isfile(os.path.join(root, d, SUMMARY))]


def particle_runs(root):
    """(directory, summary) of every run directory under root (root included)
    that holds a result file and whose summary has particles, in path order."""
    for d, _, files in sorted(os.walk(root)):
        if SUMMARY in files and RESULT in files:
            s = read_summary(d)
            if "particles" in s:
                yield d, s


def read_series(d):
    """The samples a kept run reached: one dict per row of T.csv, every column a float."""
    return [row for row in read_csv(os.path.join(d, SERIES), numbers=True) if not math.isnan(row["T"])]


def T_series(d):
    """[(t, T, T_stderr)] of the samples reached (T_stderr nan for one realization)."""
    return [(row["t"], row["T"], row["T_stderr"]) for row in read_series(d)]


def realization_columns(rows):
    """The names of the per-realization columns T_<k>, in realization order."""
    if not rows:
        return []
    return sorted((k for k in rows[0] if k.startswith("T_") and k[2:].isdigit()), key=lambda k: int(k[2:]))


def read_histogram(d):
    """histogram.csv by sample time: {t: [row, ...]}, each row a dict of floats."""
    rows = defaultdict(list)
    for row in read_csv(os.path.join(d, HISTOGRAM), numbers=True):
        rows[row["t"]].append(row)
    return rows


def write_series(h5, path):
    """T.csv from a result file (result.h5 layout: docs/output.md)."""
    import numpy as np

    t = h5["particles/t"][:]
    cols = {"t": t, "T": h5["particles/T"][:], "T_stderr": h5["particles/T_stderr"][:]}
    if "particles/realizations/T" in h5:
        rows = h5["particles/realizations/T"][:]
        if rows.shape[0] <= MAX_REALIZATION_COLUMNS:
            for i, row in enumerate(rows):
                cols["T_%d" % i] = row
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols.keys())
        for k in range(len(t)):
            w.writerow([repr(float(c[k])) if np.isfinite(c[k]) else "" for c in cols.values()])


def write_histogram(h5, path):
    """histogram.csv from a result file, when the run kept a histogram."""
    import numpy as np

    if "particles/histogram/density" not in h5:
        return
    z, t = h5["particles/histogram/z"][:], h5["particles/histogram/t"][:]
    density = h5["particles/histogram/density"][:]
    columns = {}
    if "particles/realizations/histogram_density" in h5:
        rows = h5["particles/realizations/histogram_density"][:]
        if rows.shape[0] >= 2:
            per = rows.reshape(rows.shape[0], len(t), len(z))
            columns["density_stderr"] = lambda i, j: per[:, i, j].std(ddof=1) / np.sqrt(per.shape[0])
    if "particles/histogram/exact" in h5:
        exact = h5["particles/histogram/exact"][:]
        columns["exact"] = lambda i, j: exact[j]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["t", "z", "density"] + list(columns))
        for i, ti in enumerate(t):
            for j, zj in enumerate(z):
                row = [ti, zj, density[i, j]] + [value(i, j) for value in columns.values()]
                w.writerow([repr(float(x)) for x in row])


def write_comparison(result, path):
    """A comparison of kept runs (a dict of numbers and lists) as JSON at path."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as f:
        json.dump(result, f, indent=1)


def read_comparisons(root):
    """(file name, comparison) of every COMPARISONS file directly under root, by name."""
    found = []
    for path in sorted(glob.glob(os.path.join(root, COMPARISONS))):
        with open(path) as f:
            found.append((os.path.basename(path), json.load(f)))
    return found
