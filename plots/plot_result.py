#!/usr/bin/python3
"""Plots of a shockgas result directory, read only from its result files.

Usage: /usr/bin/python3 plots/plot_result.py DIR
Writes DIR/*.png (plots/shockplot/pictures.py: one module per picture), each
whole or not at all. Exit code 3 when matplotlib or h5py is missing; 4, with one
line "cannot write PATH: REASON" on stderr, when a picture cannot be written (a
full disk).
"""
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import h5py  # noqa: F401 (draw_all reads with it: missing, exit 3 like matplotlib)
    from shockplot.pictures import draw_all
    from shockplot.saving import CannotWrite
except ImportError as exc:  # the command turns this into a warning
    print(f"plot_result.py: {exc}", file=sys.stderr)
    sys.exit(3)


def main():
    try:
        draw_all(sys.argv[1])
    except CannotWrite as exc:  # the command ends the run with this line
        print(f"plot_result.py: {exc}", file=sys.stderr)
        sys.exit(4)


if __name__ == "__main__":
    main()
