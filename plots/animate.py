#!/usr/bin/python3
"""The animation of a shockgas run, read only from its result.h5 (/animation).

Usage: /usr/bin/python3 plots/animate.py DIR
Writes DIR/animation.mp4 (ffmpeg, H.264), DIR/animation.gif and DIR/animation.png
(the last frame), each whole or not at all (plots/shockplot/movie_files.py; the
frames: movie.py). Exit code 2 when result.h5 holds no frames; 3 when
matplotlib, h5py or numpy is missing; without ffmpeg only the GIF (by Pillow)
and the PNG are written, with a warning. Exit code 4, with the line "cannot
write PATH: REASON", when the system refuses a file (a full disk).
"""
import sys

try:
    import h5py  # noqa: F401 (the frames are read with it: missing, exit 3 like matplotlib)
    import matplotlib

    matplotlib.use("Agg")
    import numpy  # noqa: F401
    from shockplot.movie_files import NoFrames, draw_animation
    from shockplot.saving import CannotWrite
except ImportError as exc:  # the command turns this into a warning
    print(f"animate.py: {exc}", file=sys.stderr)
    sys.exit(3)


def main():
    try:
        draw_animation(sys.argv[1])
    except NoFrames as exc:
        print(f"animate.py: {exc}", file=sys.stderr)
        sys.exit(2)
    except CannotWrite as exc:  # the command ends the run with this line
        print(f"animate.py: {exc}", file=sys.stderr)
        sys.exit(4)


if __name__ == "__main__":
    main()
