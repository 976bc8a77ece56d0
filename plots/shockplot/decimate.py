"""Heavy series drawn with what the pixels can show. A line of many more points
than pixel columns is drawn through, in each pixel column, its first, lowest,
highest and last point (in their order: the line's extremes and its way in and
out of the column are kept); a series of markers keeps one marker for each
pixel it covers. The figure keeps the whole series (get_xdata, get_ydata): only
what is handed to the renderer is thinned, at each draw, for the transform of
that draw (its axes, scales and resolution)."""
import numpy as np
from matplotlib.lines import Line2D

LEAST = 2000  # a series with fewer points is drawn whole


def line_points(px, py):
    """Indices, ascending, of the points (pixel coordinates px, py) a line keeps:
    per pixel column its first, last, lowest and highest point, and every point
    that is not finite together with its neighbours (a gap stays a gap)."""
    n = len(px)
    finite = np.isfinite(px) & np.isfinite(py)
    gap = np.flatnonzero(~finite)
    keep = [gap, np.clip(gap - 1, 0, n - 1), np.clip(gap + 1, 0, n - 1)]
    idx = np.flatnonzero(finite)
    if idx.size:
        run = np.cumsum(~finite)[idx]  # the finite stretch between two gaps
        column = np.floor(px[idx]).astype(np.int64)
        key = run * (column.max() - column.min() + 1) + (column - column.min())
        by_key = np.argsort(key, kind="stable")  # each column's points in the series' order
        starts = np.flatnonzero(np.r_[True, np.diff(key[by_key]) != 0])
        ends = np.r_[starts[1:], len(by_key)] - 1
        keep += [idx[by_key[starts]], idx[by_key[ends]]]
        by_height = np.lexsort((py[idx], key))  # each column's points from the lowest up
        keep += [idx[by_height[starts]], idx[by_height[ends]]]
    return np.unique(np.concatenate(keep)) if keep else np.zeros(0, int)


def marker_points(px, py):
    """Indices, ascending, of the first marker at each pixel the markers cover
    (those not finite are left out: they are not drawn)."""
    finite = np.flatnonzero(np.isfinite(px) & np.isfinite(py))
    cells = np.stack([np.floor(px[finite]), np.floor(py[finite])], axis=1)
    _, first = np.unique(cells, axis=0, return_index=True)
    return np.sort(finite[first])


def kept(line, xy):
    """The indices of xy (data coordinates, one row a point) that `line` hands
    to the renderer; None: all of them."""
    if len(xy) < LEAST:
        return None
    pixels = line.get_transform().transform(xy)
    px, py = pixels[:, 0], pixels[:, 1]
    parts = []
    if line.get_linestyle() not in ("None", "none", " ", ""):
        parts.append(line_points(px, py))
    if line.get_marker() not in (None, "None", "none", " ", ""):
        parts.append(marker_points(px, py))
    return np.unique(np.concatenate(parts)) if parts else None


class Decimated(Line2D):
    """A Line2D that draws kept() of its points."""

    def draw(self, renderer):
        x, y = self.get_xdata(orig=True), self.get_ydata(orig=True)
        xy = np.column_stack([np.asarray(x, float), np.asarray(y, float)])
        keep = kept(self, xy)
        if keep is None or len(keep) == len(xy):
            return super().draw(renderer)
        self.set_data(xy[keep, 0], xy[keep, 1])
        try:
            return super().draw(renderer)
        finally:
            self.set_data(x, y)


def decimated(lines):
    """The lines (Line2D), each made Decimated; returned as given."""
    for line in lines:
        line.__class__ = Decimated
    return lines
