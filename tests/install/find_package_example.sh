#!/bin/sh
# examples/cpp built as a user's own project against the installed prefix with
# find_package(shockgas), then run: the engine and the exact hull agree.
# usage: find_package_example.sh CMAKE PREFIX EXAMPLE_DIR WORK_DIR
set -eu
cmake=$1 prefix=$2 example=$3 work=$4
rm -rf "$work"
"$cmake" -S "$example" -B "$work" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release > "$work.log" ||
  { cat "$work.log"; exit 1; }
"$cmake" --build "$work" >> "$work.log" || { cat "$work.log"; exit 1; }
"$work/engine_vs_hull"
