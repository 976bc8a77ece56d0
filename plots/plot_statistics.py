#!/usr/bin/env python3
"""The figure page of `shockgas stats` (docs/statistics.md), drawn from statistics.csv only
(shockplot/statistics.py).

Usage: plot_statistics.py DIR   -- writes DIR/statistics.png, whole or not at all.
Exit code 3 if matplotlib is missing (the command turns that into a warning); 4,
with one line "cannot write PATH: REASON" on stderr, when it cannot be written.
"""
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    from shockplot.saving import CannotWrite
    from shockplot.statistics import draw_statistics, figure  # noqa: F401 (figure: for the tests)
except ImportError as exc:
    print(f"plot_statistics.py: {exc}", file=sys.stderr)
    sys.exit(3)


def main():
    if len(sys.argv) != 2:
        print("usage: plot_statistics.py DIR", file=sys.stderr)
        return 2
    draw_statistics(sys.argv[1])
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except CannotWrite as exc:  # the command ends with this line
        print(f"plot_statistics.py: {exc}", file=sys.stderr)
        sys.exit(4)
