#!/usr/bin/python3
"""The notebooks are stored as their author wrote them, without what a run left:
no outputs and no execution count in any code cell, no widget state in the
metadata. Reads the JSON itself (no Jupyter needed).

Usage: python3 tests/tools/check_notebooks_stripped.py DIR [MIN_COUNT]
Fails naming each notebook and cell that holds a run's traces, or when DIR holds
fewer than MIN_COUNT notebooks.
"""
import json
import pathlib
import sys


def traces(path):
    """What a run left in the notebook at path: a list of messages."""
    nb = json.loads(path.read_text())
    found = []
    for k, cell in enumerate(nb["cells"]):
        if cell["cell_type"] != "code":
            continue
        if cell.get("outputs"):
            found.append(f"{path.name}: cell {k} holds {len(cell['outputs'])} output(s)")
        if cell.get("execution_count") is not None:
            found.append(f"{path.name}: cell {k} has execution_count {cell['execution_count']}")
    if "widgets" in nb.get("metadata", {}):
        found.append(f"{path.name}: its metadata holds the widgets' state")
    return found


def main(directory, min_count="1"):
    notebooks = sorted(pathlib.Path(directory).glob("*.ipynb"))
    problems = [p for nb in notebooks for p in traces(nb)]
    if len(notebooks) < int(min_count):
        problems.append(f"{directory}: {len(notebooks)} notebooks, expected at least {min_count}")
    for p in problems:
        print(p)
    if problems:
        print("strip them: /usr/bin/python3 -m nbconvert --clear-output notebooks/*.ipynb")
        return 1
    print(f"{len(notebooks)} notebooks stored without outputs")
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
