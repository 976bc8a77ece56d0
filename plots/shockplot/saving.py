"""Writing pictures: every figure of shockgas (the run's, the animation's last
frame, the charts of `shockgas bench` and `shockgas tail`, the paper's) is
written by save(), whole or not at all, with the same PNG text: Title (its
first title), Software and Source (what it was drawn from)."""
import os

import re

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
    """The figure's first title as plain text (plain_text): its suptitle, else the first panel's that has one."""
    title = fig._suptitle.get_text() if fig._suptitle is not None else ""
    return plain_text(title or next((ax.get_title() for ax in fig.axes if ax.get_title()), ""))


# Mathtext commands as the characters they draw.
_SYMBOLS = [(r"\langle", "⟨"), (r"\rangle", "⟩"), (r"\pm", "±"), (r"\epsilon", "ε"), (r"\partial", "∂"),
            (r"\propto", "∝"), (r"\rho", "ρ"), (r"\Phi", "Φ"), (r"\sqrt", "√"), (r"\,", " "), (r"\ln", "ln"),
            (r"\min", "min"), (r"\max", "max")]
_SUPERSCRIPTS = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def plain_text(text):
    """A title's mathtext ($...$) as plain Unicode text, for the PNG's Title and so for
    report.html's captions (the page runs no scripts: no TeX is typeset there):
    "$T = \\langle v^2\\rangle$" -> "T = ⟨v²⟩", "$t^{-1/2}$" -> "t^(-1/2)", "$t_{stick}$" -> "t_stick"."""
    def math(match):
        s = match.group(1)
        for command, character in _SYMBOLS:
            s = s.replace(command, character)
        s = re.sub(r"\^\{(-?\d+)\}|\^(-?\d)", lambda m: (m.group(1) or m.group(2)).translate(_SUPERSCRIPTS), s)
        s = re.sub(r"\^\{([^}]*)\}", r"^(\1)", s)
        s = re.sub(r"_\{([^}]*)\}", r"_\1", s)
        s = re.sub(r"⟨\s*", "⟨", s)
        return s.replace("{", "").replace("}", "").replace("\\", "")
    return re.sub(r"\$([^$]*)\$", math, text)


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
