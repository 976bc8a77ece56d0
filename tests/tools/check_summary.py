#!/usr/bin/env python3
"""Checks a run's summary.json against a scene's stored expectations.

Usage: check_summary.py EXPECTED.json RUN_DIR   (its summary.json, read by
plots/shockplot/run_files.py; any python3, no numpy needed)

EXPECTED.json: {"checks": [{"key": "compare.n_shocks", ...}, ...]} where each
check has a dotted key into the summary and one or more of
  "value" with "abs_tol" and/or "rel_tol"   (a stored result, to its tolerance)
  "min", "max"                               (a bound from theory or a measured error)
and a "why" saying where the number and its tolerance come from.
Prints one line per check and "N passed, N failed"; exits 1 on any failure.
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plots"))
from shockplot.run_files import read_summary  # noqa: E402


def lookup(summary, dotted):
    node = summary
    for part in dotted.split("."):
        if isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]  # "variants.0.summary..." in a sweep's summary
        elif isinstance(node, dict) and part in node:
            node = node[part]
        else:
            raise KeyError(dotted)
    return node


def check(summary, c):
    try:
        got = lookup(summary, c["key"])
    except KeyError:
        return False, "missing"
    if isinstance(got, (int, float)) and not isinstance(got, bool) and not math.isfinite(got):
        return False, f"{got} is not finite"
    if "equals" in c:
        return got == c["equals"], f"{got!r} == {c['equals']!r}"
    ok, parts = True, []
    if "value" in c:
        tol = max(c.get("abs_tol", 0.0), c.get("rel_tol", 0.0) * abs(c["value"]))
        ok &= abs(got - c["value"]) <= tol
        parts.append(f"|{got:.6g} - {c['value']:.6g}| <= {tol:.3g}")
    if "min" in c:
        ok &= got >= c["min"]
        parts.append(f"{got:.6g} >= {c['min']:.6g}")
    if "max" in c:
        ok &= got <= c["max"]
        parts.append(f"{got:.6g} <= {c['max']:.6g}")
    return ok, ", ".join(parts)


def main():
    expected = json.load(open(sys.argv[1]))
    summary = read_summary(sys.argv[2])
    passed = failed = 0
    for c in expected["checks"]:
        ok, detail = check(summary, c)
        print(f"{'ok  ' if ok else 'FAIL'} {c['key']}: {detail}  ({c.get('why', '')})")
        passed += ok
        failed += not ok
    print(f"{passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
