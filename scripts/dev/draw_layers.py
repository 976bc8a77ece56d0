#!/usr/bin/env python3
"""The layers of shockgas as the code has them: every `#include "shockgas/..."`
of shockgas/** read, and drawn as arrows from the including module (or app room)
to the included one, into docs/img/layers.png (docs/design.md shows it).

    /usr/bin/python3 scripts/dev/draw_layers.py [--root DIR] [--out PNG]

Left, the modules (app as one box); right, the rooms of app/. Each box sits one
level above the highest box it includes (levels from the includes, not from a
list), each arrow is as thick as the includes it stands for, and its number
says how many. The order the includes must keep is the one
tests/app/test_source_rules.cpp enforces (SourceRules.IncludesRunDownTheLayers),
written here as LAYERS: an include against it is drawn red and counted in the
title, and the script exits 1.
"""
import argparse
import math
import os
import re
import sys
from collections import Counter

# The layer order of docs/design.md, as SourceRules.IncludesRunDownTheLayers holds it:
# a module includes only modules of a lower rank; particles and continuum share one.
MODULES = {"core": 0, "particles": 1, "continuum": 1, "compare": 2, "studies": 3, "app": 4}
ROOMS = ["files", "scene", "records", "directory", "output", "input", "report", "run", "ensemble", "jobs",
         "cli"]
FACADE = "shockgas.hpp"  # shockgas/shockgas.hpp: the library's one header, above everything
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]shockgas/([^">]+)[">]', re.M)


def node_of(path):
    """The module, 'app/<room>' or the facade a path under shockgas/ belongs to;
    None for a file of no folder (the generated shockgas/version.hpp)."""
    parts = path.split("/")
    if len(parts) == 1:
        return FACADE if parts[0] == FACADE else None
    if parts[0] == "app" and len(parts) > 2:
        return "app/" + parts[1]
    return parts[0]


def read_includes(root):
    """Counter of (includer, included) over every include of shockgas/** between two
    different modules or rooms."""
    edges = Counter()
    top = os.path.join(root, "shockgas")
    for folder, _, names in os.walk(top):
        for name in names:
            if not name.endswith((".hpp", ".cpp", ".h")):
                continue
            path = os.path.join(folder, name)
            src = node_of(os.path.relpath(path, top).replace(os.sep, "/"))
            with open(path, encoding="utf-8") as f:
                for included in INCLUDE.findall(f.read()):
                    dst = node_of(included)
                    if dst is not None and dst != src:
                        edges[(src, dst)] += 1
    return edges


def module_of(node):
    return node.split("/")[0]


def against_the_order(src, dst):
    """Whether an include from src to dst runs against LAYERS."""
    if dst == FACADE:
        return True
    if src == FACADE:
        return False
    ms, md = module_of(src), module_of(dst)
    if ms not in MODULES or md not in MODULES:
        return True  # a folder the order does not know
    if ms != md:
        return MODULES[md] >= MODULES[ms]
    rs, rd = src.split("/")[1], dst.split("/")[1]
    if rs not in ROOMS or rd not in ROOMS:
        return True
    return ROOMS.index(rd) > ROOMS.index(rs)


def levels(nodes, edges):
    """Each node one above the highest node it includes (longest path down)."""
    below = {n: [d for (s, d) in edges if s == n and d in nodes] for n in nodes}
    level = {}

    def of(n, seen=()):
        if n not in level:
            if n in seen:  # a cycle: drawn, not levelled
                return 0
            level[n] = 1 + max((of(d, seen + (n,)) for d in below[n]), default=-1)
        return level[n]

    for n in nodes:
        of(n)
    return level


def positions(level, order):
    """x, y of each node: its level up, the nodes of a level side by side."""
    rows = {}
    for n in sorted(level, key=order):
        rows.setdefault(level[n], []).append(n)
    pos = {}
    for y, row in rows.items():
        for i, n in enumerate(row):
            pos[n] = ((i - (len(row) - 1) / 2) * 3.0, 1.6 * y)
    return pos


def draw(ax, title, pos, edges, labels, notes):
    from matplotlib.patches import FancyArrowPatch, FancyBboxPatch

    bad = 0
    for k, ((src, dst), n) in enumerate(sorted(edges.items())):
        if src not in pos or dst not in pos:
            continue
        (x0, y0), (x1, y1) = pos[src], pos[dst]
        span = abs(y0 - y1) / 1.6
        # Arrows that skip levels bow out to one side or the other, more the further they reach.
        side = 1 if k % 2 == 0 else -1
        rad = 0 if span <= 1 and x0 == x1 else side * min(0.12 + 0.07 * span, 0.55)
        wrong = against_the_order(src, dst)
        bad += wrong * n
        colour = "tab:red" if wrong else "0.35"
        ax.add_patch(FancyArrowPatch((x0, y0 - 0.3), (x1, y1 + 0.3), connectionstyle=f"arc3,rad={rad}",
                                     arrowstyle="-|>", mutation_scale=11, color=colour,
                                     lw=0.5 + 0.6 * math.log2(n), alpha=0.75, zorder=1))
        # the count at the arc's middle: arc3's control point lies rad times the chord off its
        # middle, perpendicular to it, and the curve's middle halfway to it
        ya, yb = y0 - 0.3, y1 + 0.3
        ax.text((x0 + x1) / 2 + rad / 2 * (yb - ya), (ya + yb) / 2 - rad / 2 * (x1 - x0), str(n),
                fontsize=6.5, color=colour, ha="center", va="center", zorder=2,
                bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.85))
    for node, (x, y) in pos.items():
        ax.add_patch(FancyBboxPatch((x - 1.3, y - 0.3), 2.6, 0.6, boxstyle="round,pad=0.02",
                                    fc="#dbe9f6" if not node.startswith("(") else "#eeeeee", ec="0.2", lw=0.8,
                                    zorder=3))
        ax.text(x, y + (0.08 if node in notes else 0), labels.get(node, node), ha="center", va="center",
                fontsize=9, weight="bold", zorder=4)
        if node in notes:
            ax.text(x, y - 0.15, notes[node], ha="center", va="center", fontsize=6, color="0.3", zorder=4)
    xs = [p[0] for p in pos.values()]
    ys = [p[1] for p in pos.values()]
    reach = 0.3 * (max(ys) - min(ys))  # how far the widest arc bows out
    ax.set_xlim(min(xs) - 1.4 - reach, max(xs) + 1.4 + reach)
    ax.set_ylim(min(ys) - 0.8, max(ys) + 0.8)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(title, fontsize=10)
    return bad


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", default=os.path.normpath(os.path.join(here, "..", "..")))
    parser.add_argument("--out", default=None, help="default: ROOT/docs/img/layers.png")
    args = parser.parse_args()
    out = args.out or os.path.join(args.root, "docs", "img", "layers.png")
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        sys.path.insert(0, os.path.join(here, "..", "..", "plots"))
        from shockplot.saving import save
    except ImportError as exc:
        print(f"draw_layers.py: {exc}", file=sys.stderr)
        return 3

    edges = read_includes(args.root)
    # Left: the modules, app as one box (rooms folded into it, the facade on top).
    modules = Counter()
    for (s, d), n in edges.items():
        ms, md = module_of(s), module_of(d)
        if ms != md:
            modules[(ms, md)] += n
    mnodes = {module_of(n) for e in edges for n in e}
    morder = lambda n: (MODULES.get(n, 9), n)  # noqa: E731
    mpos = positions(levels(mnodes, modules), morder)
    # Right: the rooms of app/, and beside each room the modules below app it reaches.
    rooms = Counter({(s, d): n for (s, d), n in edges.items() if s.startswith("app/") and d.startswith("app/")})
    rnodes = {n for e in edges for n in e if n.startswith("app/")}
    reach = {}
    for (s, d), n in edges.items():
        if s.startswith("app/") and not d.startswith("app/"):
            reach.setdefault(s, set()).add(d)
    notes = {r: "+ " + ", ".join(sorted(reach[r], key=morder)) for r in reach}
    rorder = lambda n: ROOMS.index(n[4:]) if n[4:] in ROOMS else 99  # noqa: E731
    rpos = positions(levels(rnodes, rooms), rorder)

    fig, (left, right) = plt.subplots(1, 2, figsize=(14, 10), gridspec_kw={"width_ratios": [1, 1.3]})
    bad = draw(left, "modules: an arrow is #include, its number how many", mpos, modules,
               {FACADE: "shockgas/shockgas.hpp"}, {"app": "11 rooms, right"})
    bad += draw(right, "the rooms of app/ (grey: the modules each reaches below app)", rpos, rooms,
                {n: n[4:] for n in rnodes}, notes)
    total = sum(edges.values())
    fig.suptitle(f"shockgas: {total} includes between modules and rooms, read from shockgas/**; "
                 f"{bad} against the layer order", fontsize=11, color="tab:red" if bad else "black")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    save(fig, out, "the #include lines of shockgas/**", dpi=110, tight=False)
    print(f"{out}: {len(mnodes)} modules, {len(rnodes)} rooms, {total} includes, {bad} against the layer order")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
