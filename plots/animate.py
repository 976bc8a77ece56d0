#!/usr/bin/python3
"""The animation of a shockgas run, read only from its result.h5 (/animation).

Usage: /usr/bin/python3 plots/animate.py DIR [--fps N] [--size WxH] [--frames N]
Writes DIR/animation.mp4 (ffmpeg, H.264), DIR/animation.gif and DIR/animation.png
(the last frame), each whole or not at all (plots/shockplot/movie_files.py; the
frames: movie.py). --fps: frames per second (default: the frames over 8 s, 4 to
24); --size: width x height in pixels (default 1280x720); --frames: how many of
the recorded frames, spread evenly (default all). `shockgas animate` checks the
values before it calls this script. Exit code 2 when result.h5 holds no frames;
3 when matplotlib, h5py or numpy is missing; without ffmpeg only the GIF (by
Pillow) and the PNG are written, with a warning. Exit code 4, with the line
"cannot write PATH: REASON", when the system refuses a file (a full disk).
"""
import argparse
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


def size(text):
    width, height = text.lower().split("x")
    return int(width), int(height)


def main():
    parser = argparse.ArgumentParser(description="The animation of a shockgas run")
    parser.add_argument("dir")
    parser.add_argument("--fps", type=int)
    parser.add_argument("--size", type=size)
    parser.add_argument("--frames", type=int)
    args = parser.parse_args()
    try:
        draw_animation(args.dir, fps=args.fps, size=args.size, frames=args.frames)
    except NoFrames as exc:
        print(f"animate.py: {exc}", file=sys.stderr)
        sys.exit(2)
    except CannotWrite as exc:  # the command ends the run with this line
        print(f"animate.py: {exc}", file=sys.stderr)
        sys.exit(4)


if __name__ == "__main__":
    main()
