#!/bin/sh
# The scaling of an ensemble over MPI ranks, and the cost of a merge:
# `mpirun -np K shockgas run ensemble8.toml` for K = 1, 2, 3 (one thread each),
# taken in turn ROUNDS times so that a drift of the machine's speed touches
# every K alike; then the same ensemble in 4 shards and their merge.
#
# Each rank runs under /usr/bin/time, so that beside the job's wall time the
# script has every rank's CPU time (user + system). From those it prints the
# wall time the job needs when each rank has a core to itself, "CPU-bound":
# max(busiest rank, all ranks / min(K, cores)). On a machine shared with other
# work the measured wall time says how much CPU the scheduler gave the job,
# not how the ranks divide the work; the load average is printed to tell.
# docs/cluster.md quotes the medians.
# usage: bench/scaling/mpi_scaling.sh BUILD_DIR [ROUNDS]   (default 5)
set -eu
build=$(cd "$1" && pwd)
rounds=${2:-5}
here=$(cd "$(dirname "$0")" && pwd)
scene=$here/ensemble8.toml
cores=$(nproc)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mpirun="mpirun --allow-run-as-root --oversubscribe"

now() { date +%s.%N; }
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
ratio() { awk "BEGIN {printf \"%.3f\", $1 / $2}"; }

# One job of $1 ranks: appends its wall, total CPU and CPU-bound seconds to $work/{wall,cpu,bound}$1.
job() {
  ranks=$1
  start=$(now)
  $mpirun -np "$ranks" /usr/bin/time -f "rank-cpu %U %S" "$build/shockgas" run "$scene" \
    --out "$work/run$ranks" -q > /dev/null 2> "$work/stderr"
  end=$(now)
  wall=$(awk "BEGIN {print $end - $start}")
  grep '^rank-cpu' "$work/stderr" | awk -v k="$ranks" -v c="$cores" '
    { s = $2 + $3; all += s; if (s > most) most = s }
    END { per = all / (k < c ? k : c); printf "%s %s\n", all, (most > per ? most : per) }' > "$work/cpu"
  read -r cpu bound < "$work/cpu"
  echo "run ranks=$ranks round=$round wall=$wall cpu=$cpu cpu-bound=$bound"
  echo "$wall" >> "$work/wall$ranks"
  echo "$cpu" >> "$work/cpu$ranks"
  echo "$bound" >> "$work/bound$ranks"
}

echo "cores: $cores; load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
for round in $(seq 1 "$rounds"); do
  for ranks in 1 2 3; do job "$ranks"; done
  for slice in 0:2 2:4 4:6 6:8; do
    "$build/shockgas" run "$scene" --realizations "$slice" --out "$work/shard-$slice" -q > /dev/null
  done
  start=$(now)
  "$build/shockgas" merge "$work"/shard-* --out "$work/merged" -q > /dev/null
  end=$(now)
  echo "merge round=$round wall=$(awk "BEGIN {print $end - $start}")"
  awk "BEGIN {print $end - $start}" >> "$work/merge"
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"

wall1=$(median < "$work/wall1")
bound1=$(median < "$work/bound1")
for ranks in 1 2 3; do
  wall=$(median < "$work/wall$ranks") cpu=$(median < "$work/cpu$ranks") bound=$(median < "$work/bound$ranks")
  echo "median, $ranks rank(s): wall $wall s, CPU of all ranks $cpu s, CPU-bound $bound s;" \
    "speed-up over 1 rank: wall $(ratio "$wall1" "$wall"), CPU-bound $(ratio "$bound1" "$bound")"
done
merge=$(median < "$work/merge")
echo "median merge: $merge s = $(ratio "$merge" "$wall1") of the 1-rank run's wall time"
