#!/bin/sh
# examples/cpp/engine_vs_hull.cpp compiled by hand with pkg-config's flags, then run.
# usage: pkg_config_example.sh CXX PREFIX EXAMPLE_DIR WORK_DIR
set -eu
cxx=$1 prefix=$2 example=$3 work=$4
command -v pkg-config >/dev/null || { echo "skipped: no pkg-config"; exit 77; }
pc=$(find "$prefix" -name shockgas.pc | head -1)
export PKG_CONFIG_PATH=$(dirname "$pc")
rm -rf "$work" && mkdir -p "$work"
libdir=$(pkg-config --variable=libdir shockgas)
"$cxx" -std=c++20 -O2 "$example/engine_vs_hull.cpp" -o "$work/engine_vs_hull" \
  $(pkg-config --cflags --libs shockgas) -Wl,-rpath,"$libdir"
echo "pkg-config: shockgas $(pkg-config --modversion shockgas)"
"$work/engine_vs_hull"
