#!/usr/bin/python3
"""Plots of a shockgas result directory, read only from its result files.

Usage: /usr/bin/python3 plots/plot_result.py DIR [--animation]
Writes DIR/*.png (plots/shockplot/pictures.py: one module per picture) and, with
--animation, the animation (as plots/animate.py), each file whole or not at
all, by one process whose workers share the cores (shockplot/drawing.py). Exit
code 3 when matplotlib or h5py is missing; 1 when a picture failed (the last
line says which and why); 4, with the last line "cannot write PATH: REASON",
when a file cannot be written (a full disk).
"""
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import h5py  # noqa: F401 (the pictures are read with it: missing, exit 3 like matplotlib)
    from shockplot.drawing import draw_run
except ImportError as exc:  # the command turns this into a warning
    print(f"plot_result.py: {exc}", file=sys.stderr)
    sys.exit(3)


def main():
    code, last = draw_run(sys.argv[1], animation="--animation" in sys.argv[2:])
    if last:  # the command takes the last line as the reason
        print(f"plot_result.py: {last}", file=sys.stderr)
    sys.exit(code)


if __name__ == "__main__":
    main()
