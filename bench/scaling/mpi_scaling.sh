#!/bin/sh
# The scaling of an ensemble over MPI ranks, and the cost of a merge, measured
# by wall clock: `mpirun -np K shockgas run ensemble8.toml` for K = 1, 2, 3
# (one thread each), taken in turn ROUNDS times so that a drift of the
# machine's speed touches every K alike; then the same ensemble in 4 shards and
# their merge. Prints every run and the medians; docs/cluster.md quotes them.
# usage: bench/scaling/mpi_scaling.sh BUILD_DIR [ROUNDS]   (default 5)
set -eu
build=$(cd "$1" && pwd)
rounds=${2:-5}
here=$(cd "$(dirname "$0")" && pwd)
scene=$here/ensemble8.toml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mpirun="mpirun --allow-run-as-root --oversubscribe"

seconds() {  # runs "$@" and prints its wall time in seconds
  start=$(date +%s.%N)
  "$@" > /dev/null 2>&1
  end=$(date +%s.%N)
  awk "BEGIN {print $end - $start}"
}

median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

for round in $(seq 1 "$rounds"); do
  for ranks in 1 2 3; do
    s=$(seconds $mpirun -np "$ranks" "$build/shockgas" run "$scene" --out "$work/run$ranks" -q)
    echo "run ranks=$ranks round=$round seconds=$s"
    echo "$s" >> "$work/ranks$ranks"
  done
  for slice in 0:2 2:4 4:6 6:8; do
    "$build/shockgas" run "$scene" --realizations "$slice" --out "$work/shard-$slice" -q > /dev/null
  done
  s=$(seconds "$build/shockgas" merge "$work"/shard-* --out "$work/merged" -q)
  echo "merge round=$round seconds=$s"
  echo "$s" >> "$work/merge"
done

one=$(median < "$work/ranks1")
echo "median seconds: 1 rank $one, 2 ranks $(median < "$work/ranks2"), 3 ranks $(median < "$work/ranks3"), merge $(median < "$work/merge")"
for ranks in 2 3; do
  echo "speed-up with $ranks ranks: $(awk "BEGIN {printf \"%.3f\", $one / $(median < "$work/ranks$ranks")}")"
done
echo "merge / run of 1 rank: $(awk "BEGIN {printf \"%.4f\", $(median < "$work/merge") / $one}")"
