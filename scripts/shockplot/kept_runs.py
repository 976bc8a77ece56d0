"""The runs kept for docs/paper.md (data/paper-runs/), declared once, both ways:
scripts/collect_paper_run.py writes them, the paper's scripts read them.

One directory per particle run (a scene, or one variant of a sweep):
  summary.json   as the run wrote it;
  T.csv          t, T (ensemble mean), T_stderr, and T_<k> for realization k when
                 the run has at most MAX_REALIZATION_COLUMNS; empty where a
                 sample was not reached;
  histogram.csv  t, z, density (ensemble mean), and when kept density_stderr (the
                 standard error over realizations) and exact (the exact
                 mass-weighted law of the sticky gas averaged over the bin).
"""
import csv
import json
import math
import os
from collections import defaultdict

import numpy as np

SUMMARY = "summary.json"
SERIES = "T.csv"
HISTOGRAM = "histogram.csv"
MAX_REALIZATION_COLUMNS = 100

# The units of the kept quantities (docs/output.md): T is a velocity squared.
UNIT_T = "length^2/time^2"
UNIT_T_SCALED = "length^2/time^(4/3)"  # T t^(2/3)


def run_dirs(root):
    """The kept runs directly under root, by name (none if root is missing)."""
    if not os.path.isdir(root):
        return []
    return [os.path.join(root, d) for d in sorted(os.listdir(root))
            if os.path.isfile(os.path.join(root, d, SUMMARY))]


def read_summary(d, first_variant=False):
    """A run's summary.json; with first_variant, a sweep's first variant's summary."""
    with open(os.path.join(d, SUMMARY)) as f:
        s = json.load(f)
    if first_variant and "analysis" not in s and s.get("variants"):
        s = s["variants"][0]["summary"]
    return s


def _number(text):
    return float(text) if text else math.nan


def read_series(d):
    """The samples a run reached: one dict per row of T.csv, every column a float."""
    with open(os.path.join(d, SERIES)) as f:
        return [{k: _number(v) for k, v in row.items()} for row in csv.DictReader(f) if row["T"]]


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
    with open(os.path.join(d, HISTOGRAM)) as f:
        for row in csv.DictReader(f):
            rows[float(row["t"])].append({k: float(v) for k, v in row.items()})
    return rows


def write_series(h5, path):
    """T.csv from a result file (result.h5 layout: docs/output.md)."""
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
