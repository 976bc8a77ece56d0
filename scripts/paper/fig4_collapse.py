#!/usr/bin/python3
"""Fig. 4's collapse, measured: how far apart the scaled velocity distributions
Phi(z) of several restitutions r and times t are, with jackknife errors over the
realizations and the distance that noise alone would give (docs/paper.md, Figure 4).

    scripts/paper/fig4_collapse.py RUN_DIR --out data/paper-runs/fig4/collapse.json [--t-min 1e3]

RUN_DIR is a sweep of a scene over r (fig4.toml): every variant starts from the
same initial states, realization by realization, and its result.h5 keeps each
realization's mass-weighted histogram of z = (v - <v>) t^(1/3)
(particles/realizations/histogram_density). The distance of two distributions is
the L1 distance D(a, b) = sum over bins |Phi_a - Phi_b| dz, and a group's distance
the mean over its pairs, as `analysis.velocity_collapse_distance` (over the times
of one run; shockgas/compare/velocity_distribution.cpp) defines it. Groups, over the
sample times t >= t_min:

  "over t"  one r, every t (the run's own analysis.velocity_collapse_distance);
  "over r"  one t, every r (the paper's claim: Phi does not depend on r);
  "all"     every r and every t.

Errors are jackknife errors over the realization index, deleting realization i
from every variant at once (they share initial states, so the differences are
paired). The noise floor of a pair is sqrt(2/pi) sum_bins sigma_d dz, sigma_d the
jackknife error of the bin's difference: the mean |difference| of a normal
variable of zero mean, i.e. the distance of two equal distributions measured with
these realizations. A distance at its noise floor is a collapse within the
statistics. chi2 sums (difference / sigma_d)^2 over the bins where at least
MIN_REALIZATIONS realizations have mass (sigma_d of a sparser bin is itself
unreliable); bins are treated as independent, which they are only roughly (each
histogram is normalised), so chi2/dof is an indicator, not a test.

"against_exact": each r and t against the exact mass-weighted law of the r = 0
sticky gas from this white noise on the same bins (particles/histogram/exact):
the L1 distance with its jackknife error and noise floor, chi2 and its p-value.
"""
import argparse
import itertools
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plots"))
from shockplot import run_files  # noqa: E402

MIN_REALIZATIONS = 20


def variants(run_dir):
    """(r, run directory, summary) of every particle run under RUN_DIR (not RUN_DIR itself), by r."""
    found = [(s["particles"]["r"], d, s) for d, s in run_files.particle_runs(run_dir)
             if d != os.path.normpath(run_dir)]
    return sorted(found, key=lambda v: v[0])


def read_histograms(d):
    """t (times), dz, an array [realization, time, bin] of densities of run
    directory d, and the exact r = 0 law on the same bins (None if not written)."""
    with run_files.open_result(d) as h5:
        t = h5["particles/histogram/t"][:]
        z = h5["particles/histogram/z"][:]
        rows = h5["particles/realizations/histogram_density"][:]
        exact = h5["particles/histogram/exact"][:] if "particles/histogram/exact" in h5 else None
    return t, z[1] - z[0], rows.reshape(rows.shape[0], len(t), len(z)), exact


def chi2_p_value(chi2, dof):
    """P(X >= chi2) for X chi-squared with dof degrees of freedom: the regularized
    upper incomplete gamma Q(dof/2, chi2/2) (series below a + 1, continued
    fraction above; Numerical Recipes, 3rd ed., 6.2)."""
    a, x = dof / 2.0, chi2 / 2.0
    if x <= 0:
        return 1.0
    log_front = a * math.log(x) - x - math.lgamma(a)
    if x < a + 1:
        term = total = 1.0 / a
        for n in range(1, 10000):
            term *= x / (a + n)
            total += term
            if abs(term) < abs(total) * 1e-15:
                break
        return 1.0 - total * math.exp(log_front)
    b, c, d = x + 1 - a, 1e300, 1 / (x + 1 - a)
    h = d
    for n in range(1, 10000):
        an = -n * (n - a)
        b += 2
        d = 1 / (an * d + b)
        c = b + an / c
        h *= d * c
        if abs(d * c - 1) < 1e-15:
            break
    return h * math.exp(log_front)


def jackknife_error(values_without):
    """Jackknife error from the estimates with each realization left out in turn."""
    n = len(values_without)
    return math.sqrt((n - 1) / n * float(np.sum((values_without - np.mean(values_without)) ** 2)))


def leave_one_out_means(x):
    """Means of x over axis 0 with each entry left out in turn."""
    n = x.shape[0]
    return (x.sum(axis=0)[None, ...] - x) / (n - 1)


def populated(a):
    """The bins where at least MIN_REALIZATIONS realizations of a [realization, bin] have mass."""
    return np.count_nonzero(a > 0, axis=0) >= MIN_REALIZATIONS


def difference_statistics(d, use, dz):
    """Of per-realization differences d [realization, bin]: the L1 distance of
    their mean with its jackknife error, the noise floor, and chi2 and dof over
    the bins `use` whose difference has a spread."""
    n = d.shape[0]
    distance = float(np.sum(np.abs(d.mean(axis=0))) * dz)
    error = jackknife_error(np.sum(np.abs(leave_one_out_means(d)), axis=1) * dz)
    sigma = d.std(axis=0, ddof=1) / math.sqrt(n)
    floor = float(math.sqrt(2 / math.pi) * np.sum(sigma) * dz)
    use = use & (sigma > 0)
    chi2 = float(np.sum((d.mean(axis=0)[use] / sigma[use]) ** 2))
    return {"distance": distance, "error": error, "noise_floor": floor, "chi2": chi2, "dof": int(np.count_nonzero(use))}


def pair_statistics(a, b, dz):
    """Distance, its jackknife error, noise floor, chi2 and dof of two paired
    sets of per-realization densities a, b [realization, bin]."""
    return difference_statistics(a - b, populated(a) | populated(b), dz)


def exact_statistics(a, exact, dz):
    """One run's per-realization densities a [realization, bin] against the exact
    law on the same bins: as pair_statistics with the exact law as the second
    member (it has no noise of its own, so the bins are those where a has mass),
    and chi2's p-value."""
    s = difference_statistics(a - exact[None, :], populated(a), dz)
    return {**s, "p": chi2_p_value(s["chi2"], s["dof"])}


def group_statistics(members, dz):
    """Mean over pairs of the pair distance, with jackknife error and noise floor."""
    pairs = list(itertools.combinations(members, 2))
    n = members[0].shape[0]
    distance = np.mean([np.sum(np.abs(a.mean(axis=0) - b.mean(axis=0))) * dz for a, b in pairs])
    without = np.zeros(n)
    for a, b in pairs:
        without += np.sum(np.abs(leave_one_out_means(a - b)), axis=1) * dz
    without /= len(pairs)
    error = jackknife_error(without)
    floor = np.mean([pair_statistics(a, b, dz)["noise_floor"] for a, b in pairs])
    return {"distance": float(distance), "error": error, "noise_floor": float(floor), "pairs": len(pairs)}


def collapse(run_dir, t_min):
    runs = variants(run_dir)
    if len(runs) < 1:
        raise SystemExit("no particle runs with result.h5 under %s" % run_dir)
    data = {}
    dz = times = exact = None
    for r, d, _ in runs:
        t, dz, h, exact_here = read_histograms(d)
        exact = exact_here if exact is None else exact
        times = [float(x) for x in t if x >= t_min * (1 - 1e-12)]
        data[r] = {float(x): h[:, k, :] for k, x in enumerate(t) if x >= t_min * (1 - 1e-12)}
    n = min(h.shape[0] for per_t in data.values() for h in per_t.values())
    for per_t in data.values():  # the realizations common to every variant
        for t in per_t:
            per_t[t] = per_t[t][:n]
    rs = sorted(data)
    groups = []
    for r in rs:
        if len(times) >= 2:
            groups.append({"kind": "over t", "r": r, **group_statistics([data[r][t] for t in times], dz)})
    for t in times:
        if len(rs) >= 2:
            groups.append({"kind": "over r", "t": t, **group_statistics([data[r][t] for r in rs], dz)})
    everything = [data[r][t] for r in rs for t in times]
    if len(everything) >= 2:
        groups.append({"kind": "all", **group_statistics(everything, dz)})
    pairs = []
    for t in times:
        for ra, rb in itertools.combinations(rs, 2):
            pairs.append({"t": t, "r_a": ra, "r_b": rb, **pair_statistics(data[ra][t], data[rb][t], dz)})
    against_exact = [{"t": t, "r": r, **exact_statistics(data[r][t], exact, dz)} for t in times for r in rs] \
        if exact is not None else []
    own = {r: s["analysis"].get("velocity_collapse_distance") for r, _, s in runs}
    return {
        "run": os.path.basename(os.path.normpath(run_dir)),
        "git_commit": runs[0][2].get("git_commit"),
        "N": runs[0][2]["initial"]["N"],
        "realizations": n,
        "t": times,
        "r": rs,
        "bin_width": float(dz),
        "groups": groups,
        "pairs": pairs,
        "against_exact": against_exact,
        "run_summary_collapse_distance": own,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--out", required=True)
    ap.add_argument("--t-min", type=float, default=1e3, help="earliest sample time compared (default 1e3)")
    a = ap.parse_args()
    result = collapse(a.run_dir, a.t_min)
    run_files.write_comparison(result, a.out)
    for g in result["groups"]:
        where = "r = %g" % g["r"] if "r" in g else ("t = %g" % g["t"] if "t" in g else "all")
        print("%-6s %-10s D = %.4f +- %.4f  noise floor %.4f" % (g["kind"], where, g["distance"], g["error"],
                                                                g["noise_floor"]))
    for e in result["against_exact"]:
        print("exact  t = %-7g r = %-4g D = %.4f +- %.4f  noise floor %.4f  chi2 %.1f / %d  p = %.3g" % (
            e["t"], e["r"], e["distance"], e["error"], e["noise_floor"], e["chi2"], e["dof"], e["p"]))
    print("the run's own analysis.velocity_collapse_distance:", result["run_summary_collapse_distance"])


if __name__ == "__main__":
    main()
