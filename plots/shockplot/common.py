"""What every figure shares: reading the result file's attributes, axis labels
with their units, the styles (the exact solution black and dashed, each solver
in the label and colour its registration wrote), one legend per figure (saving:
saving.py)."""
import re

import numpy as np

# The exact solution, wherever it is drawn: black, dashed, named "exact".
EXACT = {"color": "black", "ls": "--", "lw": 1.4, "zorder": 5}
# Guides (a theory exponent with a fitted amplitude) and theory levels: grey.
GUIDE = {"color": "0.45", "lw": 1.1, "zorder": 4}
# Data of the particles, distinct from every solver's line.
# (tab:cyan: no solver registers it, and it is no grey beside the black exact solution)
PARTICLES = {"color": "tab:cyan", "marker": ".", "ls": "none", "ms": 2.5, "zorder": 3}
# The initial condition (t = 0): a wide pale band behind every line.
INITIAL = {"color": "0.55", "ls": "-", "lw": 3.5, "alpha": 0.35, "zorder": 0}
CLUSTER = {"marker": "v", "color": "tab:red", "ls": "none", "ms": 7}
SHOCK = {"marker": "^", "color": "tab:blue", "ls": "none", "ms": 7}


# The laws of the gas (cooling, sticky-gas, velocity scaling) are statistical:
# below this many particles a run is a few bodies, drawn without them.
GAS_PARTICLES = 100


def is_gas(summary):
    """Whether the run's particles are a gas: initial.N (of every variant of a sweep) >= GAS_PARTICLES."""
    sizes = [v.get("summary", {}).get("initial", {}).get("N") for v in summary.get("variants", [])]
    sizes.append(summary.get("initial", {}).get("N"))
    sizes = [n for n in sizes if n is not None]
    return not sizes or min(sizes) >= GAS_PARTICLES


def attr(obj, name, default=None):
    """An attribute as a Python value (text decoded), or default."""
    value = obj.attrs.get(name, default)
    return value.decode() if isinstance(value, bytes) else value


def unit(dataset):
    """The unit a dataset declares (docs/output.md), "1" for a pure number."""
    return attr(dataset, "unit", "") or "1"


def pretty_unit(unit_text):
    """A declared unit with its powers raised: "length^2/time^(4/3)" -> "length$^{2}$/time$^{4/3}$"."""
    return re.sub(r"\^(?:\((-?\d+/\d+)\)|(-?\d+))", lambda m: f"$^{{{m.group(1) or m.group(2)}}}$", unit_text or "1")


def label(name, unit_text):
    """An axis label with its unit, as declared in docs/output.md: "time $t$ [time]"; a pure number "[1]"."""
    return f"{name} [{pretty_unit(unit_text)}]"


def fraction(power, denominator=12):
    """An exponent as a short fraction: -0.6666 -> "-2/3"."""
    from fractions import Fraction
    return str(Fraction(float(power)).limit_denominator(denominator))


def solver_style(group, name):
    """A solver's line: label and colour from its registration (attributes
    label, colour of /continuum/<solver>); the exact solver black and dashed."""
    if attr(group, "exact", 0):
        return dict(EXACT, label=f"exact ({name})")
    return {"lw": 1.1, "color": attr(group, "colour"), "label": attr(group, "label", name), "zorder": 2}


def fit_amplitude(t, y, power):
    """The amplitude A of y = A t^power that fits (t, y) best in ln y (least
    squares with the exponent fixed): A = exp(mean(ln y - power ln t))."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    ok = (t > 0) & (y > 0)
    if ok.sum() == 0:
        return None
    return float(np.exp(np.mean(np.log(y[ok]) - power * np.log(t[ok]))))


def power_law(amplitude, power):
    """"0.213 t^(-2/3)" as mathtext."""
    head = f"{amplitude:.4g}\\," if amplitude is not None else ""
    return f"${head}t^{{{fraction(power)}}}$"


def draw_guide(ax, t, y, power, window, extent, text, ls=":"):
    """The power law t^power with its amplitude fitted to the data inside
    window = (t0, t1) (fit_amplitude), drawn over extent = (ta, tb). The line
    keeps its fit window and power (attributes fit_window, fit_power) so that a
    reader can check it."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    inside = (t >= window[0]) & (t <= window[1])
    amplitude = fit_amplitude(t[inside], y[inside], power)
    if amplitude is None or inside.sum() < 2:
        return None
    tt = np.geomspace(extent[0], extent[1], 50)
    (line,) = ax.plot(tt, amplitude * tt ** power, ls=ls, **GUIDE,
                      label=f"guide, {text}: {power_law(None, power)}, amplitude fitted on "
                            f"[{window[0]:.3g}, {window[1]:.3g}]")
    line.fit_window = tuple(window)
    line.fit_power = power
    return line


def figure_legend(fig, axes, columns=2, fontsize=8):
    """One legend for the whole figure, below its panels, holding every
    labelled artist of every panel once: an entry means the same thing on each
    panel it appears on, and an artist that is not in a panel is not listed."""
    seen = {}
    for ax in axes:
        for handle, text in zip(*ax.get_legend_handles_labels()):
            seen.setdefault(text, handle)
    if not seen:
        return None
    texts = sorted(seen, key=_legend_rank)  # data first, then the exact solution, fits, guides, theory
    return fig.legend([seen[t] for t in texts], texts, loc="upper center", bbox_to_anchor=(0.5, 0.0),
                      ncol=columns, fontsize=fontsize, frameon=False)


def _legend_rank(text):
    for rank, head in enumerate(("particles", "exact", "fit", "guide", "theory")):
        if text.startswith(head):
            return rank
    return 1.5  # solvers and markers: beside the exact solution


def finish(fig, axes, columns=2, fontsize=8):
    """Lays the panels out and puts the figure's one legend below them."""
    fig.tight_layout()
    return figure_legend(fig, axes, columns, fontsize)


def theory(summary, law):
    """The scope of a law of shockgas/compare/theory_scope.hpp for the run
    (summary key theory.<law>: holds, window, why), or None where it does not
    hold: a plot draws a law's value only where this is not None."""
    scope = summary.get("theory", {}).get(law)
    return scope if scope and scope.get("holds") else None


def sticky_regime_start(summary):
    """Where the sticky-gas regime's laws start to hold for the run's particles (from 10 t_stick:
    the window of theory.velocity_scaling, held to the time their data end), or None where they do not
    hold: an exact late-time law is drawn from there, not over the times before it."""
    scope = theory(summary, "velocity_scaling")
    return scope["window"][0] if scope and scope.get("window") else None


def no_theory_text(summary, law):
    """"no theory for this scene (why)" for a law that does not hold."""
    scope = summary.get("theory", {}).get(law, {})
    return f"no theory for this scene ({law}: {scope.get('why', 'not stated')})"


def note_no_theory(ax, summary, law, y=0.04):
    """The words that a law does not hold for the scene, and why, inside the panel (wrapped)."""
    import textwrap
    ax.text(0.02, y, textwrap.fill(no_theory_text(summary, law), 60), transform=ax.transAxes, fontsize=7,
            color="0.3", va="bottom")


def exponent_error_text(error, realizations=None):
    """"± e (jackknife, n realizations)" or, without an error from realizations, the words that say so."""
    if error is None:
        return "no error estimate from one realization"
    tail = f", {realizations} realizations" if realizations else ""
    return rf"$\pm$ {error:.2g} (jackknife{tail})"
