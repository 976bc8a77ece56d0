#!/bin/sh
# The wheel: built offline by pyproject.toml's own backend (in the existing build
# folder, so only the install step runs), installed into a fresh virtual
# environment (numpy from the system's site packages), imported from / and run
# on a dict scene with plots.
# usage: wheel.sh SOURCE_DIR BUILD_DIR
set -eu
source=$1 build=$2
python=/usr/bin/python3
$python -c "import build, venv" 2>/dev/null || { echo "skipped: python3-build or python3-venv missing"; exit 77; }
ls "$build"/python/shockgas/_shockgas*.so >/dev/null 2>&1 || { echo "skipped: no Python module built"; exit 77; }
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
(cd "$source" && SHOCKGAS_WHEEL_BUILD_DIR="$build" $python -m build --wheel --no-isolation --outdir "$work/dist" \
  > "$work/build.log" 2>&1) || { tail -20 "$work/build.log"; exit 1; }
wheel=$(ls "$work"/dist/*.whl)
echo "$(basename "$wheel"): $(du -k "$wheel" | cut -f1) kB"
$python -m venv --system-site-packages "$work/venv"
"$work/venv/bin/python" -m pip install --no-index --no-deps -q "$wheel"
cd / && "$work/venv/bin/python" - "$work" <<'PY'
import os, sys, shockgas
work = sys.argv[1]
assert shockgas.__file__.startswith(os.path.join(work, "venv")), shockgas.__file__
r = shockgas.run({"initial": {"N": 300, "seed": 5}, "particles": {"r": 0.5, "t_end": 30.0}},
                 out=os.path.join(work, "run"), plots=True)
pictures = [p for p in os.listdir(os.path.join(work, "run")) if p.endswith(".png")]
assert {"temperature.png", "clusters.png"} <= set(pictures), pictures  # (no regimes: r = 0.5 has none)
print("shockgas", shockgas.__version__, "imported from", os.path.dirname(shockgas.__file__), ":",
      len(pictures), "pictures")
PY
