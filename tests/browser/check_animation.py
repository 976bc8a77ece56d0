#!/usr/bin/python3
"""Checks the animation of a run: DIR/animation.mp4 has one frame per recorded
frame (/animation/t of DIR/result.h5), 1280x720 pixels, and plays (ffprobe
reads a positive duration, the frame count over the frame rate); the GIF has
the same frames, 800 pixels wide (or the movie's width, if less); the poster
PNG exists, of the movie's size. With the options of `shockgas animate`, the
animation is checked against what they asked for instead.

Usage: /usr/bin/python3 check_animation.py DIR [--size WxH] [--frames N] [--fps N]
Exit 0: passed; 1: failed; 77: skipped (no ffprobe, h5py or matplotlib).
"""
import argparse
import json
import shutil
import subprocess
import sys
from pathlib import Path

SKIP = 77

try:
    import h5py
    import matplotlib  # noqa: F401  (the frames are drawn with it)
except ImportError as exc:
    print(f"skipped: {exc} (scripts/setup installs python3-h5py and python3-matplotlib)")
    sys.exit(SKIP)
if not shutil.which("ffprobe"):
    print("skipped: ffprobe is not installed (scripts/setup installs ffmpeg)")
    sys.exit(SKIP)


def probe(path):
    out = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                          "stream=width,height,nb_read_frames,r_frame_rate:format=duration", "-of", "json", str(path)],
                         capture_output=True, text=True, check=True).stdout
    info = json.loads(out)
    s = info["streams"][0]
    num, den = (int(x) for x in s["r_frame_rate"].split("/"))
    return {"width": s["width"], "height": s["height"], "frames": int(s["nb_read_frames"]), "fps": num / den,
            "duration": float(info["format"].get("duration", 0))}


def arguments():
    parser = argparse.ArgumentParser()
    parser.add_argument("dir", type=Path)
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--frames", type=int, help="default: every recorded frame")
    parser.add_argument("--fps", type=float, help="default: any")
    return parser.parse_args()


def png_size(path):
    """Width and height of a PNG, from its IHDR chunk."""
    head = path.read_bytes()[16:24]
    return int.from_bytes(head[:4], "big"), int.from_bytes(head[4:], "big")


def main():
    args = arguments()
    run = args.dir
    width, height = (int(n) for n in args.size.split("x"))
    with h5py.File(run / "result.h5", "r") as f:
        frames = args.frames or len(f["animation/t"])
    problems = []
    mp4 = probe(run / "animation.mp4")
    print(f"animation.mp4: {mp4}")
    if (mp4["width"], mp4["height"]) != (width, height):
        problems.append(f"the MP4 is {mp4['width']}x{mp4['height']}, not {width}x{height}")
    if mp4["frames"] != frames:
        problems.append(f"the MP4 has {mp4['frames']} frames, not {frames}")
    if args.fps and mp4["fps"] != args.fps:
        problems.append(f"the MP4 plays {mp4['fps']} frames per second, not {args.fps}")
    if not abs(mp4["duration"] - frames / mp4["fps"]) <= 1.5 / mp4["fps"]:  # the container rounds to a frame
        problems.append(f"the MP4 plays {mp4['duration']} s, not {frames} frames at {mp4['fps']} per second")
    gif = probe(run / "animation.gif")
    print(f"animation.gif: {gif}")
    gif_width = min(width, 800)
    if gif["width"] != gif_width or gif["frames"] != frames:
        problems.append(f"the GIF is {gif['width']} wide with {gif['frames']} frames, not {gif_width} and {frames}")
    png = run / "animation.png"
    if not png.is_file():
        problems.append("no animation.png (the last frame)")
    elif png_size(png) != (width, height):
        problems.append(f"animation.png is {png_size(png)}, not {width}x{height}")
    for p in problems:
        print("FAIL", p)
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
