#!/usr/bin/python3
"""The animation of a shockgas run, read only from its result.h5 (/animation).

Usage: /usr/bin/python3 scripts/animate.py DIR
Writes DIR/animation.mp4 (ffmpeg, H.264), DIR/animation.gif and DIR/animation.png
(the last frame). Left: the particles as dots (clusters, coloured by mass) over
every solver's velocity and density at the same time; right: space-time, the
exact (else the first) solver's density with the clusters' paths. Exit code 3
when matplotlib, h5py or numpy is missing; without ffmpeg only the GIF and the
PNG are written (a warning on stderr).
"""
import os
import shutil
import subprocess
import sys

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.colors import LogNorm, Normalize
    from matplotlib.lines import Line2D
except ImportError as exc:  # the command turns this into a warning
    print(f"animate.py: {exc}", file=sys.stderr)
    sys.exit(3)

WIDTH, HEIGHT, DPI = 1280, 720, 100  # 720p: sharp on a projector, small as a file
GIF_WIDTH = 800
SECONDS = 8.0  # target length of the movie
MAX_TRAIL_DOTS = 4000  # cluster dots per frame in the space-time panel (the heaviest)
FEW_BODIES = 200  # up to this many bodies, the space-time panel draws every one


def text(value):
    return value.decode() if isinstance(value, bytes) else value


def unit(dataset):
    return text(dataset.attrs.get("unit", ""))


def with_unit(name, u):
    return f"{name} [{u}]" if u and u != "1" else name


class Record:
    """What the frames need, read once from result.h5."""

    def __init__(self, f):
        a = f["animation"]
        self.t = a["t"][:]
        self.t_unit = unit(a["t"])
        self.scene = text(f.attrs.get("scene_name", ""))
        self.spacing_log = self._log_spaced()
        self.clusters = self._clusters(a)
        self.fields = self._fields(f, a)
        self.measured = text(a["evolution"].attrs.get("solver", "")) if "evolution" in a else ""
        if self.measured not in self.fields and self.fields:
            self.measured = next(iter(self.fields))

    def _log_spaced(self):
        t = self.t[self.t > 0]
        return len(t) > 2 and t[-1] / t[0] > 50 and np.allclose(np.diff(np.log(t)), np.log(t[1] / t[0]), rtol=1e-6)

    @staticmethod
    def _clusters(a):
        if "clusters" not in a:
            return None
        c = a["clusters"]
        offsets = np.concatenate([[0], np.cumsum(c["count"][:].astype(int))])
        x, v, m = c["x"][:], c["v"][:], c["m"][:]
        frames = [(x[i:j], v[i:j], m[i:j]) for i, j in zip(offsets[:-1], offsets[1:])]
        return {"t": c["t"][:], "frames": frames, "x_unit": unit(c["x"]), "v_unit": unit(c["v"]),
                "m_unit": unit(c["m"])}

    @staticmethod
    def _fields(f, a):
        fields = {}
        if "fields" not in a:
            return fields
        exact = text(a["fields"].attrs.get("exact", ""))
        for name, g in a["fields"].items():
            info = f["continuum"][name].attrs if "continuum" in f and name in f["continuum"] else {}
            is_exact = name == exact
            fields[name] = {
                "x": g["x"][:], "v": g["v"][:], "rho": g["rho"][:] if "rho" in g else None,
                "label": "exact" if is_exact else text(info.get("label", name)),
                "style": {"color": "black", "ls": "--", "lw": 1.4, "zorder": 7} if is_exact
                else {"color": text(info.get("colour", None)), "lw": 1.2},
                "x_unit": unit(g["x"]), "v_unit": unit(g["v"]),
                "rho_unit": unit(g["rho"]) if "rho" in g else "",
            }
        # the exact solution drawn last, over the schemes
        return dict(sorted(fields.items(), key=lambda item: item[1]["label"] == "exact"))

    def domain(self):
        for fl in self.fields.values():
            dx = fl["x"][1] - fl["x"][0] if len(fl["x"]) > 1 else 1.0
            return fl["x"][0] - dx / 2, fl["x"][-1] + dx / 2
        xs = np.concatenate([fr[0] for fr in self.clusters["frames"]])
        pad = 0.05 * (xs.max() - xs.min() + 1e-12)
        return xs.min() - pad, xs.max() + pad

    def cluster_frame(self, k):
        """The particles' frame for frame time k: the last one reached by then."""
        c = self.clusters
        i = min(int(np.searchsorted(c["t"], self.t[k], side="right")) - 1, len(c["frames"]) - 1)
        return c["frames"][max(i, 0)], c["t"][max(i, 0)]


class Movie:
    """One figure, updated in place frame after frame."""

    def __init__(self, rec):
        self.rec = rec
        self.fig = plt.figure(figsize=(WIDTH / DPI, HEIGHT / DPI), dpi=DPI)
        grid = self.fig.add_gridspec(2, 4, width_ratios=[1.7, 0.04, 0.42, 1], left=0.075, right=0.93, top=0.87,
                                     bottom=0.09, hspace=0.1, wspace=0.05)
        self.av = self.fig.add_subplot(grid[0, 0])
        self.ar = self.fig.add_subplot(grid[1, 0], sharex=self.av)
        self.acb = self.fig.add_subplot(grid[:, 1])
        self.ast = self.fig.add_subplot(grid[:, 3])
        self.x0, self.x1 = rec.domain()
        self.norm = self._mass_norm()
        self.lines = []
        self._draw_fields()
        self._draw_particles()
        self._draw_spacetime()
        self._legend()
        self.title = self.fig.suptitle("", x=0.07, ha="left", fontsize=15)

    def _mass_norm(self):
        if self.rec.clusters is None:
            return None
        m = np.concatenate([fr[2] for fr in self.rec.clusters["frames"]])
        lo, hi = m.min(), m.max()
        return LogNorm(lo, hi) if hi > 1.5 * lo else Normalize(lo * 0.5, hi * 1.5)

    def _draw_fields(self):
        for fl in self.rec.fields.values():
            (lv,) = self.av.plot(fl["x"], fl["v"][0], label=fl["label"], **fl["style"])
            lr = None
            if fl["rho"] is not None:
                (lr,) = self.ar.plot(fl["x"], fl["rho"][0], **fl["style"])
            self.lines.append((fl, lv, lr))
        v_all = [fl["v"] for fl in self.rec.fields.values()]
        r_all = [fl["rho"] for fl in self.rec.fields.values() if fl["rho"] is not None]
        if self.rec.clusters is not None:
            v_all.append(np.concatenate([fr[1] for fr in self.rec.clusters["frames"]]))
        vlo, vhi = min(np.min(v) for v in v_all), max(np.max(v) for v in v_all)
        pad = 0.08 * (vhi - vlo + 1e-12)
        self.av.set_ylim(vlo - pad, vhi + pad)
        self.rho_log = False
        if r_all:
            rmax = max(np.max(r) for r in r_all)
            rmed = np.median(np.concatenate([r[0] for r in r_all]))
            self.rho_log = rmax > 30 * rmed
            if self.rho_log:
                self.ar.set_yscale("log")
                self.ar.set_ylim(rmed / 30, rmax * 2)
            else:
                self.ar.set_ylim(0, rmax * 1.1)
        self.av.set_xlim(self.x0, self.x1)
        units = next(iter(self.rec.fields.values()), None)
        c = self.rec.clusters
        x_unit = units["x_unit"] if units else c["x_unit"]
        self.av.set_ylabel(with_unit("velocity v", units["v_unit"] if units else c["v_unit"]), fontsize=12)
        self.ar.set_ylabel(with_unit("density ρ", units["rho_unit"] if units and units["rho_unit"]
                                     else "mass/length"), fontsize=12)
        self.ar.set_xlabel(with_unit("position x", x_unit), fontsize=12)
        plt.setp(self.av.get_xticklabels(), visible=False)

    def _dot_sizes(self, m):
        # area ~ sqrt(mass): a cluster of 100 particles is a dot 10 times the area of one
        m0 = self.rec.clusters["frames"][0][2]
        base = float(np.clip(8000.0 / max(len(m0), 1), 3.0, 60.0))
        return base * np.sqrt(m / np.min(m0))

    def _draw_particles(self):
        self.dots = self.hist = None
        if self.rec.clusters is None:
            self.acb.set_visible(False)
            return
        self.dots = self.av.scatter([], [], s=[], c=[], cmap="viridis", norm=self.norm, edgecolors="none",
                                    zorder=6)
        cb = self.fig.colorbar(self.dots, cax=self.acb)
        cb.set_label(with_unit("cluster mass", self.rec.clusters["m_unit"]), fontsize=11)
        self.edges = np.linspace(self.x0, self.x1, self._bins() + 1)
        (self.hist,) = self.ar.step(self.edges[:-1], np.zeros(len(self.edges) - 1), where="post",
                                    color="tab:green", lw=1.0, label="particles (mass per bin)")

    def _bins(self):
        # about 20 particles per bin at the start: a density, not the lattice's comb
        n = len(self.rec.clusters["frames"][0][0])
        return int(np.clip(n // 20, 20, 400))

    def _draw_spacetime(self):
        a, rec = self.ast, self.rec
        t = rec.t
        keep = t > 0 if rec.spacing_log else np.ones_like(t, dtype=bool)
        self.st_keep = keep
        if rec.fields:
            fl = rec.fields[rec.measured]
            data = fl["rho"] if fl["rho"] is not None else fl["v"]
            x = fl["x"]
            dx = x[1] - x[0]
            xe = np.concatenate([x - dx / 2, [x[-1] + dx / 2]])
            te = self._time_edges(t[keep])
            if fl["rho"] is not None:
                pos = data[keep][data[keep] > 0]
                norm = LogNorm(np.percentile(pos, 2), pos.max())
                cmap, what = "magma", with_unit(f"ρ ({fl['label']})", fl["rho_unit"])
            else:
                vmax = np.abs(data).max()
                norm, cmap, what = Normalize(-vmax, vmax), "RdBu_r", with_unit(f"v ({fl['label']})", fl["v_unit"])
            self.mesh = a.pcolormesh(xe, te, np.ma.masked_invalid(data[keep]), norm=norm, cmap=cmap,
                                     shading="flat", antialiased=False, linewidth=0, rasterized=True)
            cb = self.fig.colorbar(self.mesh, ax=a, pad=0.02, fraction=0.06)
            cb.set_label(what, fontsize=11)
        self.trail = None
        if rec.clusters is not None:
            self.trail = a.scatter([], [], s=2, c=[], cmap="viridis", norm=self.norm, edgecolors="none")
        if rec.spacing_log:
            a.set_yscale("log")
        pos = t[keep]
        a.set_ylim(pos[0] if rec.spacing_log else 0, pos[-1])
        a.set_xlim(self.x0, self.x1)
        self.now = a.axhline(pos[0], color="cyan", lw=1.5)
        a.set_xlabel(with_unit("position x", next(iter(rec.fields.values()))["x_unit"] if rec.fields
                               else rec.clusters["x_unit"]), fontsize=12)
        a.set_ylabel(with_unit("time t", rec.t_unit), fontsize=12)
        a.set_title("space-time", fontsize=12)

    def _time_edges(self, t):
        if self.rec.spacing_log:
            mid = np.sqrt(t[1:] * t[:-1])
            return np.concatenate([[t[0] ** 2 / mid[0]], mid, [t[-1] ** 2 / mid[-1]]])
        mid = 0.5 * (t[1:] + t[:-1])
        return np.concatenate([[max(t[0] - (mid[0] - t[0]), 0.0)], mid, [t[-1] + (t[-1] - mid[-1])]])

    def _legend(self):
        handles, labels = self.av.get_legend_handles_labels()
        if self.hist is not None:
            mid = plt.get_cmap("viridis")(0.5)
            handles += [Line2D([], [], ls="", marker="o", color=mid, ms=7), self.hist]
            labels += ["particles (clusters)", self.hist.get_label()]
        self.fig.legend(handles, labels, loc="upper right", ncol=min(len(labels), 4), fontsize=11,
                        frameon=False, bbox_to_anchor=(0.97, 0.995), markerscale=2)

    def update(self, k):
        rec = self.rec
        for fl, lv, lr in self.lines:
            lv.set_ydata(fl["v"][k])
            if lr is not None:
                lr.set_ydata(fl["rho"][k])
        particle_t = rec.t[k]
        if rec.clusters is not None:
            (x, v, m), particle_t = rec.cluster_frame(k)
            order = np.argsort(m)  # the heaviest on top
            self.dots.set_offsets(np.column_stack([x[order], v[order]]))
            self.dots.set_sizes(self._dot_sizes(m[order]))
            self.dots.set_array(m[order])
            hist, _ = np.histogram(x, bins=self.edges, weights=m)
            self.hist.set_ydata(np.where(hist > 0, hist / np.diff(self.edges), np.nan if self.rho_log else 0))
            self._trail(k)
        shown = rec.t[k] if not rec.spacing_log else max(rec.t[k], rec.t[rec.t > 0][0])
        self.now.set_ydata([shown, shown])
        note = "" if particle_t >= rec.t[k] else f"   (particles stopped at t = {particle_t:.4g})"
        self.title.set_text(f"{rec.scene}    t = {rec.t[k]:#.3g}{note}")

    def _trail(self, k):
        # a few bodies: every path; many: the paths of clusters only (a row of
        # single particles at each frame time would hide the picture)
        c = self.rec.clusters
        m0 = np.min(c["frames"][0][2])
        pts = []
        for i, (x, _, m) in enumerate(c["frames"]):
            ti = c["t"][i]
            if ti > self.rec.t[k] or (self.rec.spacing_log and ti <= 0):
                continue
            top = np.argsort(m)[-MAX_TRAIL_DOTS:]
            if len(m) > FEW_BODIES:
                top = top[m[top] >= 2 * m0]
            pts.append(np.column_stack([x[top], np.full(len(top), ti), m[top]]))
        if pts:
            p = np.concatenate(pts)
            self.trail.set_offsets(p[:, :2])
            self.trail.set_array(p[:, 2])

    def rgba(self):
        self.fig.canvas.draw()
        return np.asarray(self.fig.canvas.buffer_rgba())


def frames_per_second(n):
    return int(np.clip(round(n / SECONDS), 4, 24))


def encode_mp4(movie, n, fps, path):
    cmd = ["ffmpeg", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgba", "-s", f"{WIDTH}x{HEIGHT}",
           "-framerate", str(fps), "-i", "-", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "23",
           "-movflags", "+faststart", path]
    proc = subprocess.Popen(cmd, stdin=subprocess.PIPE)
    try:
        for k in range(n):
            movie.update(k)
            proc.stdin.write(movie.rgba().tobytes())
    finally:
        proc.stdin.close()
    if proc.wait() != 0:
        raise RuntimeError(f"ffmpeg failed (exit {proc.returncode}) on {path}")


def gif_from_mp4(mp4, gif, fps):
    scale = f"fps={fps},scale={GIF_WIDTH}:-1:flags=lanczos"
    subprocess.run(["ffmpeg", "-loglevel", "error", "-y", "-i", mp4, "-vf",
                    f"{scale},split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer:bayer_scale=4",
                    "-loop", "0", gif], check=True)


def gif_with_pillow(movie, n, fps, gif):
    from PIL import Image

    images = []
    for k in range(n):
        movie.update(k)
        img = Image.fromarray(movie.rgba()[:, :, :3])
        images.append(img.resize((GIF_WIDTH, GIF_WIDTH * HEIGHT // WIDTH)).convert("P", palette=Image.ADAPTIVE))
    images[0].save(gif, save_all=True, append_images=images[1:], duration=int(1000 / fps), loop=0)


def main():
    out_dir = sys.argv[1]
    with h5py.File(os.path.join(out_dir, "result.h5"), "r") as f:
        if "animation" not in f:
            print("animate.py: no /animation in result.h5 (output.animation = false)", file=sys.stderr)
            sys.exit(2)
        rec = Record(f)
    movie = Movie(rec)
    n = len(rec.t)
    fps = frames_per_second(n)
    paths = {kind: os.path.join(out_dir, "animation." + kind) for kind in ("mp4", "gif", "png")}
    if shutil.which("ffmpeg"):
        encode_mp4(movie, n, fps, paths["mp4"])
        gif_from_mp4(paths["mp4"], paths["gif"], fps)
    else:
        print("animate.py: warning: ffmpeg not found (run scripts/setup): no animation.mp4, the GIF by Pillow",
              file=sys.stderr)
        gif_with_pillow(movie, n, fps, paths["gif"])
    movie.update(n - 1)
    movie.fig.savefig(paths["png"], dpi=DPI)


if __name__ == "__main__":
    main()
