#!/usr/bin/python3
"""Plots of a shockgas result directory, read only from its result files.

Usage: /usr/bin/python3 scripts/plot_result.py DIR
Writes DIR/*.png (scripts/shockplot/: one module per picture). Exit code 3
when matplotlib or h5py is missing.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
try:
    import matplotlib

    matplotlib.use("Agg")
    from shockplot import draw_all
except ImportError as exc:  # the command turns this into a warning
    print(f"plot_result.py: {exc}", file=sys.stderr)
    sys.exit(3)


def main():
    draw_all(sys.argv[1])


if __name__ == "__main__":
    main()
