#!/bin/sh
# The command installed, its prefix moved, the sources and the build hidden: the
# default scene runs with its plots and report from the moved prefix, and
# `shockgas info` finds the run directory whole.
# usage: relocated_command.sh CMAKE BUILD_DIR SOURCE_DIR
set -eu
cmake=$1 build=$2 source=$3
. "$(dirname "$0")/hidden.sh"
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
"$cmake" --install "$build" --prefix "$work/prefix" --component cli > "$work/install.log"
mv "$work/prefix" "$work/moved"
unset SHOCKGAS_DATA_DIR SHOCKGAS_PLOT_SCRIPT
bin="$work/moved/bin/shockgas"
run_hidden "$source" "$build" "'$bin' run '$work/moved/share/shockgas/scenes/default.toml' --out '$work/run' -q && \
'$bin' info '$work/run' > '$work/info.txt'"
pictures=$(ls "$work/run"/*.png | wc -l)
[ -f "$work/run/report.html" ] || { echo "no report.html"; ls "$work/run"; exit 1; }
[ "$pictures" -ge 5 ] || { echo "only $pictures pictures"; ls "$work/run"; exit 1; }
echo "$pictures pictures and report.html from the moved prefix; shockgas info said:"
head -3 "$work/info.txt"
