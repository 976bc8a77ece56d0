"""The animation of a run written as files, each whole or not at all (by way of
NAME.partial): animation.mp4 (ffmpeg, H.264), animation.gif and animation.png
(the last frame). Without ffmpeg only the GIF (by Pillow) and the PNG, with a
warning. CannotWrite ("cannot write PATH: REASON") when the system refuses a
file (a full disk), an encoder's failure on a disk without room included."""
import errno
import os
import re
import shutil
import subprocess
import sys

import numpy as np

from .animation_data import Record
from .movie import Movie
from .run_files import open_result
from .saving import CannotWrite, write_whole

GIF_WIDTH = 800  # at most; a smaller movie's GIF has the movie's width
SECONDS = 8.0  # target length of the movie


class NoFrames(Exception):
    """The result file holds no frames (/animation): output.animation was false."""


def frames_per_second(n):
    return int(np.clip(round(n / SECONDS), 4, 24))


def refused(path, exc):
    """CannotWrite for path when exc is the system's refusal of it (an OSError
    with a reason, or an encoder that failed on a disk with no room left); else None."""
    said = getattr(exc, "said", "") or ""
    if isinstance(exc, OSError) and exc.errno not in (errno.EPIPE, None):
        return CannotWrite(f"cannot write {path}: {exc.strerror or exc}")
    no_space = os.strerror(errno.ENOSPC)
    if no_space in said or os.statvfs(os.path.dirname(os.path.abspath(path))).f_bavail == 0:
        return CannotWrite(f"cannot write {path}: {no_space}")
    return None


def written(path, write):
    """write_whole(path, write): a file whole or not at all; CannotWrite when the
    system refused it (refused)."""
    try:
        write_whole(path, write)
    except (OSError, EncoderFailed) as exc:
        cannot = refused(path, exc)
        if cannot is not None:
            raise cannot from exc
        raise


class EncoderFailed(Exception):
    """ffmpeg ended with an error: `said` is what it wrote on stderr."""

    def __init__(self, message, said):
        super().__init__(message + (": " + said.strip().splitlines()[-1] if said.strip() else ""))
        self.said = said


def ffmpeg(args, partial, fmt, stdin=None):
    """ffmpeg ARGS -f FMT PARTIAL, its stderr kept for the reason of a failure."""
    cmd = ["ffmpeg", "-loglevel", "error", "-y"] + args + ["-f", fmt, partial]
    return subprocess.Popen(cmd, stdin=stdin if stdin is not None else subprocess.DEVNULL,
                            stderr=subprocess.PIPE)


def finished(proc):
    """ffmpeg's end: EncoderFailed on a non-zero status, and also on an "Error ..."
    line with status 0, which ffmpeg returns when it cannot write the trailer or
    close the file (a full disk): the file is then cut short. ffmpeg 5 starts the
    line with "Error", later versions after the muxer's "[out#0/mp4 @ 0x...] "."""
    said = proc.stderr.read().decode(errors="replace")
    if proc.wait() != 0:
        raise EncoderFailed(f"ffmpeg failed (exit {proc.returncode})", said)
    if any(re.match(r"(\[[^]]*\] )?Error\b", line) for line in said.splitlines()):
        raise EncoderFailed("ffmpeg failed (exit 0, with errors)", said)
    if said:
        sys.stderr.write(said)


# H.264 at the SSIM against the frames of -preset medium -crf 23 (0.990 both, the
# gallery's merging-shocks), for less encoding work (1.0 s of CPU against 1.2 s)
MP4 = ["-c:v", "libx264", "-preset", "faster", "-crf", "21", "-pix_fmt", "yuv420p", "-movflags", "+faststart"]


def gif_args(width):
    """The GIF encoder's arguments for a movie `width` pixels wide."""
    return ["-vf", f"scale={min(width, GIF_WIDTH)}:-1:flags=lanczos,split[a][b];[a]palettegen=stats_mode=diff[p];"
            "[b][p]paletteuse=dither=bayer:bayer_scale=4", "-loop", "0"]


def encode(movie, frames, fps, outputs):
    """Each (path, ffmpeg arguments, format) of outputs encoded from the same
    frames (indices of the record), by encoders that run at once, each file
    whole or not at all."""
    width, height = movie.fig.canvas.get_width_height()  # the canvas's own size, to the pixel
    raw = ["-f", "rawvideo", "-pix_fmt", "rgba", "-s", f"{width}x{height}", "-framerate", str(fps), "-i", "-"]
    partials = [path + ".partial" for path, _, _ in outputs]
    procs = []
    try:
        for (_, args, fmt), partial in zip(outputs, partials):
            procs.append(ffmpeg(raw + args, partial, fmt, stdin=subprocess.PIPE))
        feed(movie, frames, procs)
        for (path, _, _), partial, proc in zip(outputs, partials, procs):
            try:
                finished(proc)
                os.replace(partial, path)
            except (OSError, EncoderFailed) as exc:
                cannot = refused(path, exc)
                if cannot is not None:
                    raise cannot from exc
                raise
    except BaseException:
        for proc in procs:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
        for partial in partials:
            if os.path.exists(partial):
                os.remove(partial)
        raise


def feed(movie, frames, procs):
    """Frame after frame to every encoder's stdin; closed at the end."""
    try:
        for k in frames:
            movie.update(k)
            frame = movie.rgba().tobytes()
            for proc in procs:
                proc.stdin.write(frame)
    except BrokenPipeError:
        pass  # an encoder stopped: its status and message say why
    finally:
        for proc in procs:
            try:
                proc.stdin.close()
            except BrokenPipeError:
                pass


def gif_with_pillow(movie, frames, fps, gif):
    from PIL import Image

    images = []
    for k in frames:
        movie.update(k)
        img = Image.fromarray(movie.rgba()[:, :, :3])
        width = min(img.width, GIF_WIDTH)
        images.append(img.resize((width, width * img.height // img.width)).convert("P", palette=Image.ADAPTIVE))
    written(gif, lambda partial: images[0].save(partial, format="GIF", save_all=True, append_images=images[1:],
                                                duration=int(1000 / fps), loop=0))


def chosen_frames(recorded, count):
    """`count` indices spread evenly over the `recorded` frames, the first and the
    last among them (all when count is None); distinct for 2 <= count <= recorded."""
    if count is None:
        return list(range(recorded))
    return [int(k) for k in np.rint(np.linspace(0, recorded - 1, count))]


def draw_animation(out_dir, who="animate.py", fps=None, size=None, frames=None):
    """animation.mp4, animation.gif and animation.png of run directory out_dir;
    `who` names the script in its warnings. NoFrames without /animation.
    fps: frames per second (None: the record's length over SECONDS, 4 to 24);
    size: (width, height) in pixels (None: 1280 x 720); frames: how many of the
    recorded frames, spread evenly (None: all). The command checks these."""
    with open_result(out_dir) as f:
        if "animation" not in f:
            raise NoFrames("no /animation in result.h5 (output.animation = false)")
        rec = Record(f)
    movie = Movie(rec, *size) if size else Movie(rec)
    shown = chosen_frames(len(rec.t), frames)
    fps = fps or frames_per_second(len(shown))
    paths = {kind: os.path.join(out_dir, "animation." + kind) for kind in ("mp4", "gif", "png")}
    if shutil.which("ffmpeg"):
        width = movie.fig.canvas.get_width_height()[0]
        encode(movie, shown, fps, [(paths["mp4"], MP4, "mp4"), (paths["gif"], gif_args(width), "gif")])
    else:
        print(f"{who}: warning: ffmpeg not found (run scripts/setup): no animation.mp4; the GIF by Pillow",
              file=sys.stderr)
        if os.path.exists(paths["mp4"]):
            os.remove(paths["mp4"])  # an older run's movie must not stand beside this one's frames
        gif_with_pillow(movie, shown, fps, paths["gif"])
    movie.update(shown[-1])
    movie.save_still(paths["png"])
