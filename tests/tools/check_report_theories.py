#!/usr/bin/env python3
"""Checks that a run states a theory only where it holds for its scene.

Usage: check_report_theories.py EXPECTED.json RUN_DIR   (any python3)

EXPECTED.json holds, beside its summary checks, the laws of
shockgas/compare/theory_scope.hpp that hold for the scene, written from its
physics (not from the code's conditions):
  "theories": {"hold": ["sticky_cooling", ...], "why": "..."}
and, for a sweep, one such entry per variant in order:
  "variant_theories": [{"hold": [...], "why": "..."}, ...]

For the run and each variant:
- summary.json's theory.<law>.holds is true exactly for the laws listed;
- report.md names a law only as "theory `<law>`", and only a listed one; every
  other mention of a theory reads "no theory for this scene";
- report.html's theory cells state the values of listed laws only (data-laws),
  and withhold (data-refused, "no theory for this scene") only laws not listed.
Prints one line per finding and "N passed, N failed"; exits 1 on any failure.
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plots"))
from shockplot.run_files import read_summary  # noqa: E402

TAG = re.compile(r"theory `(\w+)`")
NONE = "no theory for this scene"


def report_findings(text, hold):
    """(ok, message) for every theory that report.md names."""
    findings = []
    for law in TAG.findall(text):
        findings.append((law in hold, f"report.md names theory `{law}`" + ("" if law in hold else
                                                                           ": it does not hold for this scene")))
    untagged = TAG.sub("", text).replace(NONE, "")
    for line in untagged.splitlines():
        if re.search(r"\btheory\b", line, re.IGNORECASE):
            findings.append((False, f"report.md states a theory without its law's tag: {line.strip()[:120]}"))
    return findings


CELL = re.compile(r'<td class="theory"(?: data-laws="([\w ]*)")?(?: data-refused="([\w ]*)")?>(.*?)</td>')


def html_findings(text, hold):
    """(ok, message) for every theory cell of report.html's tables."""
    findings = []
    for laws, refused, value in CELL.findall(text):
        for law in laws.split():
            findings.append((law in hold, f"report.html states theory {law}'s value {value!r}" +
                             ("" if law in hold else ": it does not hold for this scene")))
        for law in refused.split():
            findings.append((law not in hold and value == NONE,
                             f"report.html withholds theory {law} ({value!r})" +
                             (": it holds for this scene" if law in hold else "")))
    return findings


def summary_findings(summary, hold):
    laws = summary.get("theory", {})
    findings = [(bool(laws), "summary.json has the theory.<law> keys")]
    for law, scope in laws.items():
        expected = law in hold
        findings.append((scope.get("holds") == expected,
                         f"theory.{law}.holds = {scope.get('holds')}, expected {expected} ({scope.get('why')})"))
    return findings


def check_run(run_dir, summary, entry):
    hold = set(entry["hold"])
    findings = summary_findings(summary, hold)
    report = os.path.join(run_dir, "report.md")
    if os.path.exists(report):
        findings += report_findings(open(report, encoding="utf-8").read(), hold)
    page = os.path.join(run_dir, "report.html")
    if os.path.exists(page):
        findings += html_findings(open(page, encoding="utf-8").read(), hold)
    return findings


def main():
    expected = json.load(open(sys.argv[1]))
    run_dir = sys.argv[2]
    summary = read_summary(run_dir)
    findings = []
    if "variant_theories" in expected:
        variants = summary.get("variants", [])
        findings.append((len(variants) == len(expected["variant_theories"]), f"{len(variants)} variants"))
        for variant, entry in zip(variants, expected["variant_theories"]):
            directory = os.path.join(run_dir, variant.get("directory", ""))
            findings += check_run(directory, variant["summary"], entry)
    else:
        findings += check_run(run_dir, summary, expected["theories"])
    passed = sum(ok for ok, _ in findings)
    for ok, message in findings:
        print(f"{'ok  ' if ok else 'FAIL'} {message}")
    print(f"{passed} passed, {len(findings) - passed} failed")
    sys.exit(0 if passed == len(findings) else 1)


if __name__ == "__main__":
    main()
