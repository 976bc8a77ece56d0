"""Scenes as the command runs them: shockgas.run, run_toml, load.

A scene is what `shockgas run SCENE.toml` reads: one table per part ([initial],
[particles], [continuum], [compare], [output], [scene], [sweep]); a table that is
present runs that part. Every key, with its unit, default and allowed values, is
listed by shockgas.scene_keys() and in docs/scenes.md. The outputs are named as
in docs/output.md, whether kept in memory or written to a directory.
"""

import os
import warnings

from . import _shockgas
from ._progress import Progress


class SolverNote(UserWarning):
    """What the run chose for the scene (particles.solver = "auto": the hull or the
    event engine, and why): the note `shockgas run` prints as "shockgas: note: ...".
    Silence it with warnings.simplefilter("ignore", shockgas.SolverNote)."""


class Result:
    """The outputs of a run, named as result.h5 and summary.json name them
    (docs/output.md; shockgas.output_layout() lists every name with its unit).

    datasets      {"/particles/T": array, ...}: every dataset of result.h5, as
                  numpy arrays (matrices 2-D, rows first)
    units         {"/particles/T": "length^2/time^2", ...}; descriptions likewise
    attributes    {"/particles@stop_reason": "completed", ...}: text, or a number
                  where the layout gives a unit
    summary       summary.json as a nested dict: the figures of merit
    figures       the same flattened to dotted keys: {"analysis.T_exponent": -0.66, ...}
    directory     where the files were written (None if only in memory)
    notes         what the run chose for the scene and why, as `shockgas run`
                  notes it (also issued as SolverNote warnings by run)

    result[name] looks up a dataset ("/particles/T"), an attribute
    ("/particles@stop_reason") or a figure ("analysis.T_exponent");
    result.to_xarray() gives the fields and series as an xarray.Dataset.
    """

    def __init__(self, outputs):
        self.datasets = outputs["datasets"]
        self.units = outputs["units"]
        self.descriptions = outputs["descriptions"]
        self.attributes = outputs["attributes"]
        self.summary = outputs["summary"]
        self.directory = outputs["directory"]
        self.notes = outputs.get("notes", [])
        self.figures = dict(_flatten(self.summary))

    def __getitem__(self, name):
        for table in (self.datasets, self.attributes, self.figures):
            if name in table:
                return table[name]
        raise KeyError(f"{name!r}: not a dataset, attribute or summary key of this result "
                       "(see .datasets, .attributes, .figures)")

    def to_xarray(self):
        """The fields and series as an xarray.Dataset: coordinates solver, x and t,
        units and descriptions in the attributes of each variable, the scene in the
        Dataset's (shockgas/_xarray.py; needs python3-xarray)."""
        from ._xarray import to_xarray  # noqa: PLC0415 (xarray only when asked for)

        return to_xarray(self)

    def __contains__(self, name):
        return name in self.datasets or name in self.attributes or name in self.figures

    def __repr__(self):
        where = f"directory={self.directory!r}, " if self.directory else ""
        return (f"Result({where}{len(self.datasets)} datasets, {len(self.attributes)} attributes, "
                f"{len(self.figures)} figures)")


def _flatten(tree, prefix=""):
    for key, value in tree.items():
        if isinstance(value, dict):
            yield from _flatten(value, prefix + key + ".")
        else:
            yield prefix + key, value


def run(scene, overrides=None, out=None, plots=True, progress=None):
    """Run a scene as `shockgas run` does; the outputs in memory.

    scene      path of a scene file (.toml), or the scene as a nested dict,
               {"initial": {"N": 1000}, "particles": {"r": 0.5, "t_end": 1e3}}
    overrides  {"particles.r": 0.5, ...}: keys set over the scene's (the
               command's --set)
    out        a directory: also write result.h5, summary.json, report.md,
               report.html (and plots) there, as the command does; None: memory
               only. Files are
               written under temporary names and renamed when complete, so an
               interrupted or failed run leaves no file that looks whole.
    plots      with out: make the PNG plots (needs matplotlib)
    progress   None, True (a bar per stage), or progress(stage, fraction, time)

    Returns a Result. A [sweep] scene needs out (each variant gets a directory);
    its Result holds the sweep's own file.

    Raises shockgas.InputError (a ValueError) for a key or value the scene does not
    allow, before any work, naming the key and where it was set
    (scene['particles']['r'], overrides['particles.r'] or file:line);
    RuntimeError if the run fails; KeyboardInterrupt on Ctrl-C (the computation
    stops at its next safe point).
    """
    with Progress(progress) as callback:
        if isinstance(scene, dict):
            text = _shockgas._dict_scene_text(scene)
            outputs = _shockgas._run_text(text, _shockgas._dict_origin, overrides, _path(out), plots, callback)
        else:
            outputs = _shockgas._run_path(os.fspath(scene), overrides, _path(out), plots, callback)
    return _noted(Result(outputs))


def run_toml(text, overrides=None, out=None, plots=True, progress=None):
    """Run a scene given as TOML text; as shockgas.run (messages name "<toml>:LINE")."""
    with Progress(progress) as callback:
        outputs = _shockgas._run_text(text, "<toml>", overrides, _path(out), plots, callback)
    return _noted(Result(outputs))


def load(path):
    """The Result of a finished run, read from its result.h5 (path: the file or its
    directory) and summary.json beside it: the same object shockgas.run returns."""
    return Result(_shockgas._load(os.fspath(path)))


def scene_keys():
    """Every scene key: a list of dicts with table, key, kind, unit, default (as
    TOML), doc and allowed, from the declarations the parser uses."""
    return _shockgas._scene_keys()


def output_layout():
    """Every dataset, attribute and summary key a run may write: a list of dicts
    with kind, path ({solver}, {k} stand for a solver's name, an index), unit,
    description and when (docs/output.md)."""
    return _shockgas._layout()


def _noted(result):
    """The result, its notes issued as SolverNote warnings (at the caller of run)."""
    for note in result.notes:
        warnings.warn(note, SolverNote, stacklevel=3)
    return result


def _path(out):
    return None if out is None else os.fspath(out)
