"""Writing pictures: every figure of shockgas (the run's, the animation's last
frame, the charts of `shockgas bench` and `shockgas tail`, the paper's) is
written by save(), whole or not at all, with the same PNG text: Title (its
first title), Software and Source (what it was drawn from)."""
import os

import matplotlib
import matplotlib.pyplot as plt

DPI = 110  # the run's pictures
PAD = 0.1  # inches around a cropped picture (matplotlib's savefig.pad_inches)
SOFTWARE = f"shockgas (plots/shockplot, matplotlib {matplotlib.__version__})"


class CannotWrite(Exception):
    """A picture that could not be written: "cannot write PATH: REASON"."""


def write_whole(path, write):
    """Calls write(partial) for path's NAME.partial, then renames it to path: a file
    whole or not at all. On a failure the partial file is removed and the error
    goes on."""
    partial = path + ".partial"
    try:
        write(partial)
        os.replace(partial, path)
    except BaseException:
        if os.path.exists(partial):
            os.remove(partial)
        raise


def save_whole(path, write):
    """write_whole(path, write), a refusal of the system (a full disk) raised as
    CannotWrite("cannot write PATH: REASON")."""
    try:
        write_whole(path, write)
    except OSError as exc:
        raise CannotWrite(f"cannot write {path}: {exc.strerror or exc}") from exc


def title_of(fig):
    """The figure's first title: its suptitle, else the first panel's that has one."""
    title = fig._suptitle.get_text() if fig._suptitle is not None else ""
    return title or next((ax.get_title() for ax in fig.axes if ax.get_title()), "")


def save(fig, path, source, dpi=DPI, tight=True):
    """Writes the figure as the PNG `path`, whole or not at all (write_whole), and
    closes it. PNG text: Title (title_of), Software, Source (`source`: what the
    picture was drawn from, e.g. "result.h5, summary.json"). tight: cropped to
    what is drawn (a legend below the panels included), else the figure's own
    size. CannotWrite when the system refuses the file (a full disk)."""
    metadata = {"Software": SOFTWARE, "Source": source}
    title = title_of(fig)
    if title:
        metadata["Title"] = title
    try:
        # The crop of bbox_inches="tight", measured here: savefig then skips the
        # whole draw it makes first to measure it (the same pixels, a draw less).
        fig.set_dpi(dpi)  # measured at the resolution it is written at
        crop = fig.get_tightbbox(fig.canvas.get_renderer()).padded(PAD) if tight else None
        save_whole(path, lambda partial: fig.savefig(partial, format="png", dpi=dpi, metadata=metadata,
                                                     bbox_inches=crop))
    finally:
        plt.close(fig)
