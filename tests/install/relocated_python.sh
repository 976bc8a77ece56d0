#!/bin/sh
# The Python module installed, its prefix moved, the sources and the build hidden:
# from /, `import shockgas` runs a small scene given as a dict, with its plots.
# usage: relocated_python.sh CMAKE BUILD_DIR SOURCE_DIR
set -eu
cmake=$1 build=$2 source=$3
. "$(dirname "$0")/hidden.sh"
[ -x /usr/bin/python3 ] || { echo "skipped: no /usr/bin/python3"; exit 77; }
ls "$build"/python/shockgas/_shockgas*.so >/dev/null 2>&1 || { echo "skipped: no Python module built"; exit 77; }
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
"$cmake" --install "$build" --prefix "$work/prefix" --component python > "$work/install.log"
mv "$work/prefix" "$work/moved"
site=$(dirname "$(find "$work/moved" -name __init__.py -path '*/shockgas/*' | head -1)")
unset SHOCKGAS_DATA_DIR SHOCKGAS_PLOT_SCRIPT
cat > "$work/check.py" <<PY
import os, shockgas
assert os.path.dirname(shockgas.__file__) == "$site", shockgas.__file__
scene = {"initial": {"N": 400, "seed": 3}, "particles": {"r": 0.5, "t_end": 50.0}}
r = shockgas.run(scene, out="$work/run", plots=True)
pictures = sorted(p for p in os.listdir("$work/run") if p.endswith(".png"))
assert {"temperature.png", "clusters.png"} <= set(pictures), pictures  # a particles-only scene's
print("shockgas", shockgas.__version__, "from", os.path.dirname(shockgas.__file__), ":", len(pictures), "pictures")
PY
run_hidden "$source" "$build" "cd / && PYTHONPATH='$(dirname "$site")' /usr/bin/python3 '$work/check.py'"
