"""The animation's clusters as dots, sized and coloured by mass, the heaviest on
top. A scatter draws each dot on its own (about 2.7 us a dot: 50 ms a frame of
20 000 particles); a mass that many dots share is drawn instead as one line of
markers, which Agg renders once and stamps. The lightest masses, each held by
at least MIN_GROUP dots, are such groups, lightest first; the first mass with
fewer dots and every heavier one stay in the scatter, drawn last: the order of
the dots by mass is kept."""
import numpy as np
from matplotlib.lines import Line2D

MIN_GROUP = 64


class MassDots:
    """Updates `scatter` (a PathCollection of ax, coloured by its cmap and
    norm, sizes in points^2) and the groups that stand in for it."""

    def __init__(self, ax, scatter):
        self.ax, self.scatter, self.groups = ax, scatter, []

    def artists(self):
        """What to draw, in order: the groups, lightest first, then the scatter."""
        return self.groups + [self.scatter]

    def set_animated(self, animated):
        for a in self.artists():
            a.set_animated(animated)

    def update(self, x, v, m, sizes):
        """Dots at (x, v) of masses m (ascending) and sizes (points^2)."""
        masses, first, counts = np.unique(m, return_index=True, return_counts=True)
        grouped = 0
        while grouped < len(masses) and counts[grouped] >= MIN_GROUP:
            grouped += 1
        for k in range(grouped):
            line = self._group(k)
            at = slice(first[k], first[k] + counts[k])
            line.set_data(x[at], v[at])
            line.set_markersize(np.sqrt(sizes[first[k]]))
            line.set_color(self.scatter.cmap(self.scatter.norm(masses[k])))
            line.set_visible(True)
        for line in self.groups[grouped:]:
            line.set_visible(False)
        rest = slice(first[grouped], None) if grouped < len(masses) else slice(0, 0)
        self.scatter.set_offsets(np.column_stack([x[rest], v[rest]]))
        self.scatter.set_sizes(sizes[rest])
        self.scatter.set_array(m[rest])

    def _group(self, k):
        while len(self.groups) <= k:
            line = Line2D([], [], ls="none", marker="o", markeredgewidth=0, zorder=self.scatter.get_zorder(),
                          animated=self.scatter.get_animated())
            self.groups.append(self.ax.add_line(line))
        return self.groups[k]
