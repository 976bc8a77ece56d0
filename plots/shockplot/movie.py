"""The animation's frames (plots/animate.py, and the run's plots with
--animation): one figure of 1280 x 720 pixels (or the size asked for: the same
picture, its fonts and lines scaled with the width) updated in place frame after
frame. Left: the particles as dots (clusters, coloured by mass) over every
solver's velocity and density at the same time; right: space-time, the exact
(else the first) solver's density with the paths of the heaviest clusters.
Frames are read once from result.h5 (animation_data.py)."""
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.colors import LogNorm, Normalize
from matplotlib.lines import Line2D

from .animation_data import with_unit
from .decimate import decimated
from .log_ticks import install as install_log_ticks
from .log_ticks import label_colorbar
from .mass_dots import MassDots
from .run_files import RESULT
from .saving import save

install_log_ticks()  # tick labels of log axes as text, not mathtext (log_ticks.py)

WIDTH, HEIGHT, DPI = 1280, 720, 100  # 720p: sharp on a projector, small as a file
FEW_BODIES = 200  # up to this many bodies, the space-time panel draws every one's path
TRAIL_CLUSTERS = 12  # else the paths of this many heaviest clusters (of 5 particles or more)
CMAP = "viridis"  # cluster mass
PARTICLE_DENSITY = "tab:pink"  # a colour no registered solver uses


class Movie:
    """One figure, updated in place frame after frame."""

    def __init__(self, rec, width=WIDTH, height=HEIGHT):
        self.rec = rec
        self.dpi = DPI * width / WIDTH
        self.fig = plt.figure(figsize=(inches(width, self.dpi), inches(height, self.dpi)), dpi=self.dpi)
        grid = self.fig.add_gridspec(2, 4, width_ratios=[1.7, 0.04, 0.42, 1], left=0.075, right=0.93, top=0.86,
                                     bottom=0.09, hspace=0.1, wspace=0.05)
        self.grid = grid
        self.av = self.fig.add_subplot(grid[0, 0])
        self.ar = self.fig.add_subplot(grid[1, 0], sharex=self.av)
        self.acb = self.fig.add_subplot(grid[:, 1])
        self.ast = self.fig.add_subplot(grid[:, 3])
        self.norm = self._mass_norm()
        self._draw_fields()
        self._draw_particles()
        self._draw_spacetime()
        self._legend()
        self.title = self.fig.suptitle("", x=0.075, y=0.985, ha="left", va="top", fontsize=15)
        self.background = None

    def _mass_norm(self):
        if self.rec.clusters is None:
            return None
        m = np.concatenate([fr[2] for fr in self.rec.clusters["frames"]])
        lo, hi = m.min(), m.max()
        return LogNorm(lo, hi) if hi > 1.5 * lo else Normalize(lo * 0.5, hi * 1.5)

    def _draw_fields(self):
        rec = self.rec
        self.lines = []
        for fl in rec.fields.values():
            (lv,) = decimated(self.av.plot(fl["x"], fl["v"][0], label=fl["label"], **fl["style"]))
            lr = None
            if fl["rho"] is not None:  # no baseline: no edge down to 0 at the domain's ends
                lr = self.ar.stairs(fl["rho_bins"][0], rec.edges, baseline=None, **fl["style"])
            self.lines.append((fl, lv, lr))
        v_all = [fl["v"] for fl in rec.fields.values()]
        if rec.clusters is not None:
            v_all.append(np.concatenate([fr[1] for fr in rec.clusters["frames"]]))
        vlo, vhi = min(np.min(v) for v in v_all), max(np.max(v) for v in v_all)
        pad = 0.08 * (vhi - vlo + 1e-12)
        self.av.set_ylim(vlo - pad, vhi + pad)
        self.zoom = rec.spacing_log  # decades of cooling: the velocity axis follows each frame
        x_unit, v_unit, rho_unit = rec.units()
        self.av.set_xlim(rec.x0, rec.x1)
        self.av.set_ylabel(with_unit("velocity v", v_unit), fontsize=12)
        per_bin = f" (bins of {rec.cells_per_bin} cells)" if rec.cells_per_bin > 1 else ""
        self.ar.set_ylabel(with_unit("density ρ", rho_unit) + per_bin, fontsize=12)
        self.ar.set_xlabel(with_unit("position x", x_unit), fontsize=12)
        self.av.tick_params(labelbottom=False)
        self._density_axis()

    def _density_axis(self):
        rec = self.rec
        rows = [fl["rho_bins"] for fl in rec.fields.values() if fl["rho"] is not None]
        few = rec.clusters is not None and len(rec.clusters["frames"][0][0]) <= FEW_BODIES
        if rec.clusters is not None and not few:
            rows.append(np.array([rec.particle_density(k) for k in range(len(rec.t))]))
        self.rho_log = False
        if not rows:  # a few bodies and no field: no density to speak of; v takes the column
            self.ar.set_visible(False)
            self.av.set_position(self.grid[:, 0].get_position(self.fig))
            self.av.tick_params(labelbottom=True)
            self.av.set_xlabel(with_unit("position x", rec.units()[0]), fontsize=12)
            return
        rmax = max(np.max(r) for r in rows)
        first = np.concatenate([r[0] for r in rows])
        rmed = np.median(first[first > 0]) if np.any(first > 0) else rmax
        self.rho_log = rmax > 30 * rmed
        if self.rho_log:
            self.ar.set_yscale("log")
            self.ar.set_ylim(rmed / 30, rmax * 2)
        else:
            self.ar.set_ylim(0, rmax * 1.1)

    def _draw_particles(self):
        self.dots = self.hist = self.mass_dots = None
        if self.rec.clusters is None:
            self.acb.set_visible(False)
            return
        self.dots = self.av.scatter([], [], s=[], c=[], cmap=CMAP, norm=self.norm, edgecolors="none", zorder=8)
        self.mass_dots = MassDots(self.av, self.dots)
        if isinstance(self.norm, LogNorm):
            cb = self.fig.colorbar(self.dots, cax=self.acb)
            label_colorbar(cb)
            cb.set_label(with_unit("cluster mass", self.rec.clusters["m_unit"]), fontsize=11)
        else:  # one mass throughout: no scale to read
            self.acb.set_visible(False)
        if self.ar.get_visible():
            self.hist = self.ar.stairs(self.rec.particle_density(0), self.rec.particle_edges, baseline=None,
                                       color=PARTICLE_DENSITY, lw=1.0, label="particles (mass per bin)")

    def _dot_sizes(self, m):
        # area ~ sqrt(mass): a cluster of 100 particles is a dot 10 times the area of one
        base = float(np.clip(8000.0 / len(self.rec.clusters["frames"][0][2]), 5.0, 60.0))
        return base * np.sqrt(m / self.rec.clusters["m0"])

    def _draw_spacetime(self):
        a, rec = self.ast, self.rec
        keep = rec.t > 0 if rec.spacing_log else np.ones_like(rec.t, dtype=bool)
        if rec.fields:
            self._spacetime_image(keep)
        self.trail = None
        if rec.clusters is not None:
            self.trail = a.scatter([], [], s=4, c=[], cmap=CMAP, norm=self.norm, edgecolors="none")
        if rec.spacing_log:
            a.set_yscale("log")
        t = rec.t[keep]
        a.set_ylim(t[0] if rec.spacing_log else 0, t[-1])
        a.set_xlim(rec.x0, rec.x1)
        self.now = a.axhline(t[0], color="cyan", lw=1.5)
        x_unit, _, _ = rec.units()
        a.set_xlabel(with_unit("position x", x_unit), fontsize=12)
        a.set_ylabel(with_unit("time t", rec.t_unit), fontsize=12)
        a.set_title("space-time", fontsize=12)

    def _spacetime_image(self, keep):
        rec = self.rec
        fl = rec.fields[rec.measured]
        te = self._time_edges(rec.t[keep])
        if fl["rho"] is not None:
            rho, xe = rec.spacetime_density(fl)
            data = np.ma.masked_less_equal(rho[keep], 0)
            # four decades below the densest: a fan's vacuum (0, or rounding) is dark
            norm = LogNorm(max(np.percentile(data.compressed(), 2), 1e-4 * data.max()), data.max())
            cmap, what = plt.get_cmap("magma").copy(), with_unit(f"ρ ({fl['label']})", fl["rho_unit"])
            cmap.set_bad(cmap(0.0))  # vacuum: as dark as the thinnest gas
        else:
            data = fl["v"][keep]
            vmax = np.abs(data).max()
            dx = fl["x"][1] - fl["x"][0]
            xe = np.append(fl["x"] - dx / 2, fl["x"][-1] + dx / 2)
            norm, cmap, what = Normalize(-vmax, vmax), "RdBu_r", with_unit(f"v ({fl['label']})", fl["v_unit"])
        mesh = self.ast.pcolormesh(xe, te, data, norm=norm, cmap=cmap, shading="flat", antialiased=False,
                                   linewidth=0, rasterized=True)
        cb = self.fig.colorbar(mesh, ax=self.ast, pad=0.02, fraction=0.06)
        if isinstance(norm, LogNorm):
            label_colorbar(cb)
        cb.set_label(what, fontsize=11)

    def _time_edges(self, t):
        if self.rec.spacing_log:
            mid = np.sqrt(t[1:] * t[:-1])
            return np.concatenate([[t[0] ** 2 / mid[0]], mid, [t[-1] ** 2 / mid[-1]]])
        mid = 0.5 * (t[1:] + t[:-1])
        return np.concatenate([[max(t[0] - (mid[0] - t[0]), 0.0)], mid, [t[-1] + (t[-1] - mid[-1])]])

    def _legend(self):
        handles, labels = self.av.get_legend_handles_labels()
        if self.dots is not None:
            handles.append(Line2D([], [], ls="", marker="o", color=plt.get_cmap(CMAP)(0.5), ms=7))
            labels.append("particles (clusters)")
        if self.hist is not None:
            handles.append(Line2D([], [], color=PARTICLE_DENSITY))
            labels.append(self.hist.get_label())
        self.fig.legend(handles, labels, loc="upper left", ncol=min(len(labels), 5), fontsize=10.5,
                        frameon=False, bbox_to_anchor=(0.07, 0.945), columnspacing=1.5, handlelength=2.5)

    def update(self, k):
        rec = self.rec
        for fl, lv, lr in self.lines:
            lv.set_ydata(fl["v"][k])
            if lr is not None:
                lr.set_data(values=fl["rho_bins"][k])
        particle_t = rec.t[k]
        if rec.clusters is not None:
            (x, v, m), particle_t = rec.cluster_frame(k)
            order = np.argsort(m)  # the heaviest on top
            self.mass_dots.update(x[order], v[order], m[order], self._dot_sizes(m[order]))
            if self.hist is not None:
                self.hist.set_data(values=rec.particle_density(k))
            self._trail(k)
        if self.zoom:
            self._zoom_velocity(k)
        shown = max(rec.t[k], rec.t[rec.t > 0][0]) if rec.spacing_log else rec.t[k]
        self.now.set_ydata([shown, shown])
        note = "" if particle_t >= rec.t[k] else f"   (particles: {rec.stop[0]} at t = {rec.stop[1]:.4g})"
        self.title.set_text(f"{rec.scene}    t = {time_text(rec.t[k])}{note}")

    def _zoom_velocity(self, k):
        vmax = max((np.max(np.abs(fl["v"][k])) for fl in self.rec.fields.values()), default=0.0)
        if self.rec.clusters is not None:
            vmax = max(vmax, np.max(np.abs(self.rec.cluster_frame(k)[0][1])))
        self.av.set_ylim(-1.1 * vmax, 1.1 * vmax)

    def _trail(self, k):
        pts = [p for ti, p in self._trail_points() if ti <= self.rec.t[k]]
        if pts:
            p = np.concatenate(pts)
            self.trail.set_offsets(p[:, :2])
            self.trail.set_array(p[:, 2])

    def _trail_points(self):
        """(t, [x, t, m] rows) of each particle frame's trail points, found once.
        A few bodies: every path; many: the heaviest clusters' (a row of
        particles at each frame time would hide the picture)."""
        if getattr(self, "trail_points", None) is None:
            c = self.rec.clusters
            self.trail_points = []
            for i, (x, _, m) in enumerate(c["frames"]):
                ti = c["t"][i]
                if self.rec.spacing_log and ti <= 0:
                    continue
                top = np.arange(len(m))
                if len(m) > FEW_BODIES:
                    top = np.argsort(m)[-TRAIL_CLUSTERS:]
                    top = top[m[top] >= 5 * c["m0"]]
                self.trail_points.append((ti, np.column_stack([x[top], np.full(len(top), ti), m[top]])))
        return self.trail_points

    def _moving(self):
        """What changes from frame to frame, in the order it is drawn: the
        velocity panel's lines and dots by their zorder, then the densities, the
        title, the space-time panel's time line and trail."""
        inside = [lv for _, lv, _ in self.lines] + (self.mass_dots.artists() if self.mass_dots else [])
        parts = [lr for _, _, lr in self.lines if lr is not None] + [self.title, self.now]
        return sorted(inside, key=lambda a: a.get_zorder()) + parts + [a for a in (self.hist, self.trail)
                                                                        if a is not None]

    def rgba(self):
        """The frame's pixels. What does not move (the panels with their axes,
        the space-time image, colour bars, legend) is drawn once and restored;
        each frame draws what moves, and the velocity axis when it follows the
        frames (zoom)."""
        canvas = self.fig.canvas
        if self.background is None:
            for a in self._moving():
                a.set_animated(True)
            self.av.yaxis.set_visible(not self.zoom)
            canvas.draw()
            self.background = canvas.copy_from_bbox(self.fig.bbox)
            self.av.yaxis.set_visible(True)
        canvas.restore_region(self.background)
        renderer = canvas.get_renderer()
        if self.zoom:
            self.av.yaxis.draw(renderer)
        for a in self._moving():
            a.draw(renderer)
        return np.asarray(canvas.buffer_rgba())

    def save_still(self, path):
        """The frame shown as a picture (animation.png), of the movie's size."""
        for a in self._moving():
            a.set_animated(False)
        save(self.fig, path, RESULT, dpi=self.dpi, tight=False)


def inches(pixels, dpi):
    """pixels / dpi, nudged up where inches * dpi rounds below pixels: the canvas
    truncates that product to whole pixels."""
    size = pixels / dpi
    while int(size * dpi) < pixels:
        size = np.nextafter(size, np.inf)
    return size


def time_text(t):
    return f"{t:,.0f}" if t >= 100 else f"{t:.3g}"
