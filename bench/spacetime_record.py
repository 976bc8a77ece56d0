"""The space-time record's size against its picture: fewer world lines or coarser positions.

Reads a result file whose /particles/spacetime/x holds every particle (the
default scene run with --set particles.spacetime_particles=N) and writes the
record again, the way shockgas writes it (hdf5_file_write.cpp: chunks of about
2^16 values, whole rows; shuffle, deflate 4, Fletcher32), in each variant:

  lines K   the world lines of K particles evenly spaced in label, the first
            and the last always (particles/run_result.hpp: spacetime_labels),
            float32 as the layout declares;
  step q    every world line, positions rounded to a multiple of q (lengths
            are in units of the mean spacing) and stored as float32;
  uint16    every world line, x L / 65536 as a 16-bit integer (0.3 spacings at N = 2e4).

For each: the bytes of the dataset, the file's size with it (the rest of the
file as it is), and spacetime.png drawn from it by plots/shockplot/spacetime.py
with the fraction of the pixels of its panel that differ from the whole record's.

    /usr/bin/python3 bench/spacetime_record.py FILE --pictures DIR
"""

import argparse
import os
import sys
import tempfile

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from shockplot.saving import DPI, save  # noqa: E402
from shockplot.spacetime import figure_spacetime  # noqa: E402

CHUNK_VALUES = 1 << 16
RECORD = "particles/spacetime"


def labels_of(n, most):
    """As spacetime_labels() in shockgas/particles/run_result.hpp."""
    k = min(n, most)
    return np.array([0] if k == 1 else [j * (n - 1) // (k - 1) for j in range(k)], dtype=np.int64)


def chunk_shape(shape):
    """As chunk_shape() in hdf5_file_write.cpp (also bench/deflate_levels.py)."""
    cols = min(max(shape[1], 1), CHUNK_VALUES)
    return (min(max(CHUNK_VALUES // cols, 1), max(shape[0], 1)), cols)


def variants(x, length):
    n = x.shape[1]
    for k in (n, 500, 1000, 2000, 5000, 10000):  # the whole record first: the reference picture
        if k == n or k < n:
            labels = labels_of(n, k)
            yield f"lines {k}", labels, x[:, labels].astype(np.float32), None
    every = np.arange(n, dtype=np.int64)
    for q in (0.25, 1.0):
        yield f"step {q:g}", every, (np.round(x / q) * q).astype(np.float32), None
    scale = 65536.0 / length
    yield "uint16", every, np.minimum(np.floor(x * scale), 65535).astype(np.uint16), scale


def write_record(target, t, labels, stored, units):
    with h5py.File(target, "w", libver="latest") as f:
        g = f.create_group(RECORD)
        g.create_dataset("t", data=t).attrs["unit"] = units["t"]
        g.create_dataset("label", data=labels).attrs["unit"] = "1"
        d = g.create_dataset("x", data=stored, chunks=chunk_shape(stored.shape), shuffle=True, fletcher32=True,
                             compression="gzip", compression_opts=4)
        d.attrs["unit"] = units["x"]
        return d.id.get_storage_size()


def draw(t, labels, x, units, png):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "drawn.h5")
        with h5py.File(path, "w") as f:
            g = f.create_group(RECORD)
            g.create_dataset("t", data=t).attrs["unit"] = units["t"]
            g.create_dataset("label", data=labels)
            g.create_dataset("x", data=x).attrs["unit"] = units["x"]
        with h5py.File(path, "r") as f:
            fig = figure_spacetime(f)
    fig.set_dpi(DPI)
    fig.canvas.draw()
    box = fig.axes[0].get_window_extent()  # the panel alone: the titles differ in words
    pixels = np.asarray(fig.canvas.buffer_rgba())[..., :3].astype(float) / 255
    height = pixels.shape[0]
    panel = pixels[int(height - box.y1):int(height - box.y0), int(box.x0):int(box.x1)]
    save(fig, png, "bench/spacetime_record.py")  # as the run saves its pictures
    return panel


def main():
    p = argparse.ArgumentParser()
    p.add_argument("file")
    p.add_argument("--pictures", required=True, help="directory for the spacetime PNG of each variant")
    a = p.parse_args()
    os.makedirs(a.pictures, exist_ok=True)
    with h5py.File(a.file, "r") as f:
        s = f[RECORD]
        t, x = s["t"][:], s["x"][:].astype(np.float64)
        units = {"t": s["t"].attrs["unit"], "x": s["x"].attrs["unit"]}
        whole_bytes = s["x"].id.get_storage_size()
    length = float(x.shape[1])  # L = N: a lattice ring of unit spacing
    rest = os.path.getsize(a.file) - whole_bytes
    reference = None
    print(f"the file without the record: {rest / 1e6:.2f} MB ({x.shape[0]} frames x {x.shape[1]} particles)")
    print("| variant | record (MB) | result.h5 (MB) | largest position error | pixels differing |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for name, labels, stored, scale in variants(x, length):
            size = write_record(os.path.join(tmp, "record.h5"), t, labels, stored, units)
            drawn = stored / scale if scale else stored.astype(np.float64)
            error = np.abs(drawn - x[:, labels]).max() if scale or name.startswith("step") else 0.0
            image = draw(t, labels, drawn, units, os.path.join(a.pictures, name.replace(" ", "_") + ".png"))
            reference = image if reference is None else reference
            differ = np.any(np.abs(image - reference) > 0.1, axis=-1).mean()
            print(f"| {name} | {size / 1e6:.2f} | {(rest + size) / 1e6:.2f} | {error:.3g} | {100 * differ:.2f} % |")


if __name__ == "__main__":
    main()
