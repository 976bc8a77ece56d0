"""A run's outputs as an xarray.Dataset (Result.to_xarray(); docs/output.md, "From Python").

Coordinates:
    solver  the continuum solvers that wrote fields (/continuum/{solver})
    x       the cell centres of their grid (/continuum/{solver}/x, one grid for all)
    t       the particles' log-spaced sample times (/particles/t)
Data variables:
    v, rho            (solver, x): each solver's fields at t_end (rho NaN for a
                      solver without a density; attribute t_end: their time)
    T, mean_v, ...    (t): the particles' ensemble series, each with its _stderr
    count             (t): realizations that reached each sample
Every variable and coordinate carries its unit and description as attributes
(the layout's); the Dataset's attributes hold the scene (scene_name,
scene_text, resolved_parameters) and the provenance (layout_version,
shockgas_version, git_commit, created_utc).

xarray (Debian: python3-xarray) is imported only here, when asked for.
"""

import numpy as np

_FILE_ATTRIBUTES = ("layout_version", "scene_name", "scene_text", "resolved_parameters", "shockgas_version",
                    "git_commit", "created_utc", "overrides")


def _attrs(result, path):
    out = {"unit": result.units.get(path, "")}
    if result.descriptions.get(path):
        out["description"] = result.descriptions[path]
    return out


def _solvers(datasets):
    names = set()
    for path in datasets:
        parts = path.split("/")
        if len(parts) == 4 and parts[1] == "continuum" and parts[3] == "v":
            names.add(parts[2])
    return sorted(names)


def _fields(result, coords, data):
    d = result.datasets
    solvers = _solvers(d)
    if not solvers:
        return
    x_path = f"/continuum/{solvers[0]}/x"
    x = np.asarray(d[x_path], dtype=np.float64)
    for s in solvers[1:]:
        if not np.array_equal(np.asarray(d[f"/continuum/{s}/x"], dtype=np.float64), x):
            raise ValueError(f"solver {s!r} has a grid other than {solvers[0]!r}'s: no common coordinate x")
    coords["solver"] = ("solver", np.array(solvers),
                        {"unit": "1", "description": "continuum solver (/continuum/{solver})"})
    coords["x"] = ("x", x, _attrs(result, x_path))
    for field in ("v", "rho"):
        rows = [d.get(f"/continuum/{s}/{field}") for s in solvers]
        if all(r is None for r in rows):
            continue
        values = np.full((len(solvers), x.size), np.nan)
        for i, r in enumerate(rows):
            if r is not None:
                values[i] = r
        path = next(f"/continuum/{s}/{field}" for s, r in zip(solvers, rows) if r is not None)
        attrs = _attrs(result, path)
        t_end = result.attributes.get(f"/continuum/{solvers[0]}@t")
        if t_end is not None:  # the fields' own time: the coordinate t holds the particles' samples
            attrs["t_end"] = float(t_end)
            text = attrs.get("description", field)
            text = text[: -len(" at t")] + " at t_end" if text.endswith(" at t") else text
            attrs["description"] = text + " (attribute t_end; the coordinate t holds the particles' sample times)"
        data[field] = (("solver", "x"), values, attrs)


def _series(result, coords, data):
    d = result.datasets
    if "/particles/t" not in d:
        return
    t = np.asarray(d["/particles/t"])
    coords["t"] = ("t", t, _attrs(result, "/particles/t"))
    for path, values in d.items():
        parts = path.split("/")
        if len(parts) == 3 and parts[1] == "particles" and parts[2] != "t" and np.shape(values) == t.shape:
            data[parts[2]] = ("t", np.asarray(values), _attrs(result, path))


def to_xarray(result):
    """The Dataset described above, from a Result (shockgas.load or shockgas.run)."""
    import xarray  # noqa: PLC0415 (optional dependency)

    coords, data = {}, {}
    _fields(result, coords, data)
    _series(result, coords, data)
    attrs = {name: result.attributes["/@" + name] for name in _FILE_ATTRIBUTES if "/@" + name in result.attributes}
    attrs.setdefault("layout_version", "1.0")  # a file without the attribute is of layout 1.0
    if result.directory:
        attrs["directory"] = str(result.directory)
    return xarray.Dataset(data_vars=data, coords=coords, attrs=attrs)
