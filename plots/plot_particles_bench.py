#!/usr/bin/python3
"""Chart of particles_bench's CSV: whole-process rate (per CPU second) and peak
memory against N, and the thread scaling of one realization (wall clock).

    /usr/bin/python3 plots/plot_particles_bench.py particles_bench.csv particles_bench.png
"""
import os
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from shockplot.run_files import read_csv  # noqa: E402
from shockplot.saving import save  # noqa: E402


def read(path):
    rows = [r for r in read_csv(path) if r["ok"] == "1"]
    for r in rows:
        for key in ("N", "threads", "collisions"):
            r[key] = int(r[key])
        for key in ("t_end", "wall_s", "cpu_s", "peak_bytes", "bytes_per_particle", "rate_wall_per_s",
                    "rate_cpu_per_s"):
            r[key] = float(r[key])
    return rows


def series(rows, case, engine):
    pts = sorted((r["N"], r) for r in rows if r["case"] == case and r["engine"] == engine)
    return [n for n, _ in pts], [r for _, r in pts]


def main(csv_path, png_path):
    rows = read(csv_path)
    fig, (rate_ax, mem_ax, thr_ax) = plt.subplots(1, 3, figsize=(15, 4.6))
    styles = {("engine", "short"): ("C0", "-o"), ("engine", "long"): ("C0", "--s"),
              ("baseline", "short"): ("C3", "-o"), ("baseline", "long"): ("C3", "--s")}
    for (engine, case), (color, style) in styles.items():
        n, rs = series(rows, case, engine)
        if not n:
            continue
        t_end = rs[0]["t_end"]
        label = f"{'engine' if engine == 'engine' else 'priority-queue baseline'}, t = {t_end:g}"
        rate_ax.plot(n, [r["rate_cpu_per_s"] / 1e6 for r in rs], style, color=color, label=label)
        mem_ax.plot(n, [r["peak_bytes"] / 2**20 for r in rs], style, color=color, label=label)
    # Per CPU second of the whole process: on a shared machine its wall clock also
    # counts the time others held the core.
    rate_ax.set(xscale="log", xlabel="particles N", ylabel="collisions per CPU second of the whole process [10^6/s]",
                title="Rate, one thread (40 samples, clusters on)")
    sizes = sorted({r["N"] for r in rows if r["case"] != "scaling"})
    if sizes:
        fixed = min(r["peak_bytes"] for r in rows)  # the smallest process: what does not grow with N
        mem_ax.plot(sizes, [(fixed + 40 * n) / 2**20 for n in sizes], ":", color="k",
                    label=f"40 bytes per particle + {fixed / 2**20:.0f} MiB")
    mem_ax.set(xscale="log", yscale="log", xlabel="particles N", ylabel="peak memory [MiB]",
               title="Peak memory of the whole process")
    scaling = [r for r in rows if r["case"] == "scaling"]
    if scaling:
        threads = sorted({r["threads"] for r in scaling})
        walls = [statistics.median(r["wall_s"] for r in scaling if r["threads"] == k) for k in threads]
        speedup = [walls[0] / w for w in walls]
        thr_ax.plot(threads, speedup, "-o", color="C0", label="median of the runs")
        for k in threads:
            runs = [walls[0] / r["wall_s"] for r in scaling if r["threads"] == k]
            thr_ax.plot([k] * len(runs), runs, ".", color="C0", alpha=0.4)
        thr_ax.plot(threads, threads, ":", color="k", label="ideal")
        s = scaling[0]
        thr_ax.set(xlabel="threads", ylabel="speed-up over one thread (wall clock)", xticks=threads,
                   title=f"One realization, N = {s['N']:.0e}, t = {s['t_end']:g}")
    for ax in (rate_ax, mem_ax, thr_ax):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, png_path, os.path.basename(csv_path), dpi=110, tight=False)
    print("wrote", png_path)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
