"""Log-axis tick labels as plain text (10³, 2×10², 10⁻², −10¹), the labels
matplotlib writes in mathtext ($\\mathdefault{10^{3}}$), whose parse costs about
5 ms per distinct label: 0.35 s of the default scene's 2.3 s of drawing.
install() replaces the "log" and "symlog" scales of this process by ones
whose formatters give the text (matplotlib.scale.register_scale),
label_colorbar() does it for a colorbar of a log norm; a label of another
form is left as matplotlib wrote it."""
import re

from matplotlib import scale, ticker

_POWER = re.compile(r"\$\\mathdefault\{(-?)(?:([0-9.]+)\\times)?10\^\{(-?\d+)\}\}\$")
_NUMBER = re.compile(r"\$\\mathdefault\{(-?)([0-9.]+)\}\$")
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
MINUS = "\N{MINUS SIGN}"


def as_text(label):
    """A mathtext tick label of LogFormatterSciNotation as plain text."""
    power = _POWER.fullmatch(label)
    if power:
        sign, coefficient, exponent = power.groups()
        mantissa = f"{coefficient}×10" if coefficient else "10"
        return (MINUS if sign else "") + mantissa + exponent.translate(_SUPERSCRIPT)
    number = _NUMBER.fullmatch(label)
    if number:
        return (MINUS if number.group(1) else "") + number.group(2)
    return label


class TextLogFormatter(ticker.LogFormatterSciNotation):
    """LogFormatterSciNotation's labels, as plain text."""

    def __call__(self, x, pos=None):
        return as_text(super().__call__(x, pos))


class TextLogScale(scale.LogScale):
    def set_default_locators_and_formatters(self, axis):
        super().set_default_locators_and_formatters(axis)
        axis.set_major_formatter(TextLogFormatter(self.base))
        axis.set_minor_formatter(TextLogFormatter(self.base, labelOnlyBase=(self.subs is not None)))


class TextSymmetricalLogScale(scale.SymmetricalLogScale):
    def set_default_locators_and_formatters(self, axis):
        super().set_default_locators_and_formatters(axis)
        axis.set_major_formatter(TextLogFormatter(self.base))


def label_colorbar(cb):
    """A colorbar of a log norm labelled in text (a colorbar sets its own
    formatter on its long axis, not the scale's)."""
    axis = cb.ax.yaxis if cb.orientation == "vertical" else cb.ax.xaxis
    axis.set_major_formatter(TextLogFormatter())
    axis.set_minor_formatter(TextLogFormatter(labelOnlyBase=True))


def install():
    """The scales "log" and "symlog" of this process, with text labels."""
    scale.register_scale(TextLogScale)
    scale.register_scale(TextSymmetricalLogScale)
