"""The frames of a shockgas run as plots/animate.py draws them, read once from
result.h5 (/animation, see docs/output.md): the particles' clusters per frame and
every solver's fields, with their labels, colours and units from the file.

Densities are shown as cell averages over display bins of at most MAX_BINS
bins (a block of cells each, mass kept): a delta-shock is then a bin holding
its mass, not a spike too thin for the screen, and the particles' mass per bin
is drawn on the same bins.
"""
import numpy as np

MAX_BINS = 600
MAX_SPACETIME_BINS = 200  # the space-time panel is about 300 pixels wide: a bin a pixel or more


def text(value):
    return value.decode() if isinstance(value, bytes) else value


def unit(dataset):
    return text(dataset.attrs.get("unit", ""))


def with_unit(name, u):
    return f"{name} [{u}]" if u and u != "1" else name


def block_edges(cells, max_bins=MAX_BINS):
    """Indices of the first cell of each display bin, and the cells per bin."""
    per_bin = max(1, -(-cells // max_bins))
    starts = np.arange(0, cells, per_bin)
    return starts, per_bin


def block_mean(rows, starts):
    """Row-wise mean of each block of cells (the last block may be shorter)."""
    sums = np.add.reduceat(rows, starts, axis=-1)
    sizes = np.diff(np.append(starts, rows.shape[-1]))
    return sums / sizes


class Record:
    """What the frames need, read once from result.h5."""

    def __init__(self, f):
        a = f["animation"]
        self.t = a["t"][:]
        self.t_unit = unit(a["t"])
        self.scene = text(f.attrs.get("scene_name", ""))
        p = f["particles"].attrs if "particles" in f else {}
        self.stop = (text(p.get("stop_reason", "")), float(p.get("stop_time", 0.0)))  # how the particles ended
        self.spacing_log = self._log_spaced()
        self.clusters = self._clusters(a)
        self.fields = self._fields(f, a)
        self.measured = text(a["evolution"].attrs.get("solver", "")) if "evolution" in a else ""
        if self.measured not in self.fields and self.fields:
            self.measured = next(iter(self.fields))
        self.x0, self.x1 = self._domain()
        self.edges, self.cells_per_bin = self._display_bins()
        self.particle_edges = self._particle_bins()

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
                "m_unit": unit(c["m"]), "m0": float(np.min(frames[0][2]))}

    @staticmethod
    def _fields(f, a):
        fields = {}
        if "fields" not in a:
            return fields
        exact = text(a["fields"].attrs.get("exact", ""))
        for name, g in a["fields"].items():
            info = f["continuum"][name].attrs if "continuum" in f and name in f["continuum"] else {}
            is_exact = name == exact
            dense = len(g["x"]) > 1000  # many cells: thin lines, so that the particles show through
            fields[name] = {
                "x": g["x"][:], "v": g["v"][:], "rho": g["rho"][:] if "rho" in g else None,
                "label": "exact" if is_exact else text(info.get("label", name)),
                "style": {"color": "black", "ls": "--", "lw": 0.8 if dense else 1.4, "zorder": 7} if is_exact
                else {"color": text(info.get("colour", None)), "lw": 0.7 if dense else 1.2},
                "x_unit": unit(g["x"]), "v_unit": unit(g["v"]),
                "rho_unit": unit(g["rho"]) if "rho" in g else "",
            }
        # the exact solution drawn last, over the schemes
        return dict(sorted(fields.items(), key=lambda item: item[1]["label"] == "exact"))

    def _domain(self):
        for fl in self.fields.values():
            dx = fl["x"][1] - fl["x"][0] if len(fl["x"]) > 1 else 1.0
            return fl["x"][0] - dx / 2, fl["x"][-1] + dx / 2
        xs = np.concatenate([fr[0] for fr in self.clusters["frames"]])
        pad = 0.05 * (xs.max() - xs.min() + 1e-12)
        return xs.min() - pad, xs.max() + pad

    def _display_bins(self):
        """Display bins of the fields: blocks of their cells (else the particles' bins)."""
        for fl in self.fields.values():
            starts, per_bin = block_edges(len(fl["x"]))
            dx = (self.x1 - self.x0) / len(fl["x"])
            for g in self.fields.values():
                if g["rho"] is not None:
                    g["rho_bins"] = block_mean(g["rho"], starts)
            return np.append(self.x0 + starts * dx, self.x1), per_bin
        return self._particle_bins(), 0

    def _particle_bins(self):
        """Bins holding about 20 particles each at the start (a density, not the
        lattice's comb), never finer than the fields' display bins."""
        if self.clusters is None:
            return None
        bins = int(np.clip(len(self.clusters["frames"][0][0]) // 20, 20, 400))
        if self.fields:
            bins = min(bins, len(self.edges) - 1)
        return np.linspace(self.x0, self.x1, bins + 1)

    def spacetime_density(self, fl):
        """The field's density on at most MAX_SPACETIME_BINS bins (mass kept, so that a
        delta-shock stays a bright bin rather than falling between pixels), and their edges."""
        starts, _ = block_edges(len(fl["x"]), MAX_SPACETIME_BINS)
        dx = (self.x1 - self.x0) / len(fl["x"])
        return block_mean(fl["rho"], starts), np.append(self.x0 + starts * dx, self.x1)

    def cluster_frame(self, k):
        """The particles' frame for frame time k: the last one reached by then, and its time."""
        c = self.clusters
        i = min(int(np.searchsorted(c["t"], self.t[k], side="right")) - 1, len(c["frames"]) - 1)
        return c["frames"][max(i, 0)], c["t"][max(i, 0)]

    def particle_density(self, k):
        """The particles' mass per display bin over its width, at frame k."""
        (x, _, m), _ = self.cluster_frame(k)
        hist, _ = np.histogram(x, bins=self.particle_edges, weights=m)
        return hist / np.diff(self.particle_edges)

    def units(self):
        """x, v, rho units, from the fields if any, else the particles."""
        fl = next(iter(self.fields.values()), None)
        if fl:
            return fl["x_unit"], fl["v_unit"], fl["rho_unit"] or "mass/length"
        c = self.clusters
        return c["x_unit"], c["v_unit"], "mass/length"
