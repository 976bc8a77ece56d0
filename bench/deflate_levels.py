"""zlib's level for result.h5: write time against size.

Rewrites the datasets of a run's result file (RUN: a run directory or its
result.h5, of either layout) the way shockgas writes them now (hdf5_file_write.cpp):
chunks of about 2^16 values (whole rows of a matrix), shuffle, deflate at each
level, Fletcher32, the latest file format; each dataset in the type its layout
declares (`shockgas info --layout`, its type column: float32 for drawn data, int64 for counts).
h5py calls the same libhdf5 and zlib as shockgas, so the time per level is
zlib's cost on these data. Process CPU time (the machine may be shared); levels
alternate round after round and the median of the rounds is printed.

    /usr/bin/python3 bench/deflate_levels.py RUN [--types build/shockgas] [--rounds 5]

RUN for docs/performance/command.md's table (every world line of the default scene):
    build/shockgas run data/scenes/default.toml --set particles.spacetime_particles=20000 \
        --out out/default-all-lines --no-plots
"""

import argparse
import os
import statistics
import subprocess
import tempfile
import time

import h5py
import numpy as np

CHUNK_VALUES = 1 << 16


def chunk_shape(shape):
    """As chunk_shape() in hdf5_file_write.cpp."""
    if len(shape) == 1:
        return (min(max(shape[0], 1), CHUNK_VALUES),)
    cols = min(max(shape[1], 1), CHUNK_VALUES)
    return (min(max(CHUNK_VALUES // cols, 1), max(shape[0], 1)), cols)


def declared_types(binary):
    """{path pattern: type name} from the type column of `shockgas info --layout`; {} without a binary."""
    if not binary:
        return {}
    out = subprocess.run([binary, "info", "--layout"], capture_output=True, text=True, check=True).stdout
    types = {}
    for line in out.splitlines():
        cells = [c.strip() for c in line.split("|")]
        if len(cells) > 5 and cells[1].startswith("`/") and cells[3] in ("float64", "float32", "int64"):
            types[cells[1].strip("`")] = cells[3]
    return types


def type_of(path, types):
    for pattern, name in types.items():
        head, _, tail = pattern.partition("{")
        if pattern == path or ("{" in pattern and path.startswith(head)
                               and path.endswith(tail.partition("}")[2])):
            return {"float32": np.float32, "int64": np.int64}.get(name, np.float64)
    return np.float64


def read_all(path, types):
    data = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: data.__setitem__("/" + name, obj[()].astype(
            type_of("/" + name, types))) if isinstance(obj, h5py.Dataset) else None)
    return data


def write(data, target, level):
    start = time.process_time()
    with h5py.File(target, "w", libver="latest") as f:
        for name, values in data.items():
            if values.ndim == 0:
                f[name] = values
                continue
            opts = {"chunks": chunk_shape(values.shape), "shuffle": True, "fletcher32": True}
            if level > 0:
                opts.update(compression="gzip", compression_opts=level)
            f.create_dataset(name, data=values, maxshape=tuple(None if n == 0 else n for n in values.shape),
                             **opts)
    return time.process_time() - start, os.path.getsize(target)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("run", help="a run directory (its result.h5) or a result file")
    p.add_argument("--types", default="", help="a shockgas binary whose layout gives the types")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--levels", default="0,1,2,3,4,6,9")
    a = p.parse_args()
    file = os.path.join(a.run, "result.h5") if os.path.isdir(a.run) else a.run
    data = read_all(file, declared_types(a.types))
    levels = [int(x) for x in a.levels.split(",")]
    times = {level: [] for level in levels}
    sizes = {}
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(a.rounds):
            for level in levels:
                seconds, sizes[level] = write(data, os.path.join(tmp, f"l{level}.h5"), level)
                times[level].append(seconds)
    print("| deflate level | size (MB) | write CPU time (s), median | spread (min-max) |")
    print("|---|---|---|---|")
    for level in levels:
        t = times[level]
        print(f"| {level} | {sizes[level] / 1e6:.2f} | {statistics.median(t):.3f} | {min(t):.3f}-{max(t):.3f} |")


if __name__ == "__main__":
    main()
