#!/usr/bin/python3
"""Executes a notebook of notebooks/ top to bottom with nbclient, as an instructor's
"Run All" would: the test fails on the first cell that raises, among them the
notebook's own `assert`s of its numbers against theory.

Usage: /usr/bin/python3 tests/tools/run_notebook.py NOTEBOOK.ipynb

The kernel is this interpreter (sys.executable, /usr/bin/python3 under CTest),
named explicitly, so a kernel "python3" installed elsewhere (another Python,
without numpy) is never the one that runs. The module comes from PYTHONPATH
(CTest: the build's python/). Exit 77 (CTest's skip) with a message where
nbclient, nbformat or ipykernel is missing; the executed notebook is not saved.
"""
import json
import pathlib
import sys
import tempfile
import time

SKIP = 77
KERNEL = "shockgas-test-python"


def missing_jupyter():
    """The name of the first missing package, or None."""
    for name in ("nbclient", "nbformat", "ipykernel", "jupyter_client"):
        try:
            __import__(name)
        except ImportError:
            return name
    return None


def kernel_manager(kernel_dir):
    """A KernelManager whose only kernel is this interpreter's ipykernel."""
    from jupyter_client.kernelspec import KernelSpecManager
    from jupyter_client.manager import KernelManager

    spec_dir = pathlib.Path(kernel_dir) / KERNEL
    spec_dir.mkdir()
    spec = {"argv": [sys.executable, "-Xfrozen_modules=off", "-m", "ipykernel_launcher", "-f", "{connection_file}"],
            "display_name": f"Python ({sys.executable})", "language": "python"}
    (spec_dir / "kernel.json").write_text(json.dumps(spec))
    specs = KernelSpecManager(kernel_dirs=[str(kernel_dir)], ensure_native_kernel=False)
    return KernelManager(kernel_name=KERNEL, kernel_spec_manager=specs)


def code_asserts(nb):
    """The number of code lines that start with `assert`."""
    return sum(line.lstrip().startswith("assert ")
               for cell in nb.cells if cell.cell_type == "code"
               for line in cell.source.splitlines())


def main(path):
    absent = missing_jupyter()
    if absent:
        print(f"skipped: {absent} is missing for {sys.executable} (Debian: python3-nbclient "
              "python3-ipykernel python3-ipywidgets jupyter-notebook; scripts/setup installs them)")
        return SKIP
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError

    nb = nbformat.read(path, as_version=4)
    asserts = code_asserts(nb)
    if asserts == 0:
        print(f"{path}: no assert: a notebook checks its own numbers")
        return 1
    start = time.monotonic()
    with tempfile.TemporaryDirectory() as kernel_dir:
        client = NotebookClient(nb, km=kernel_manager(kernel_dir), timeout=600, store_widget_state=False,
                                resources={"metadata": {"path": str(pathlib.Path(path).parent)}})
        # nbclient mimics the front end of ipywidgets 7 and later, whose first message
        # carries a "state"; Debian 12's ipywidgets 6 sends none. No front end is
        # needed: the sliders' values are read by the notebook itself.
        client.comm_open_handlers = {"jupyter.widget": lambda msg: None}
        try:
            client.execute()
        except CellExecutionError as exc:
            print(f"{path}: a cell failed\n{exc}")
            return 1
    print(f"{path}: {len(nb.cells)} cells and their {asserts} asserts ran in "
          f"{time.monotonic() - start:.1f} s under {sys.executable}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
