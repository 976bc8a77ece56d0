#!/bin/sh
# A rank killed (SIGKILL) while it runs a realization stops the job: one
# shockgas message names the rank and the realization, and no result is written.
# usage: killed_rank.sh SHOCKGAS MPIRUN SCENE OUT
set -u
shockgas=$1 mpirun=$2 scene=$3 out=$4
rm -rf "$out"
mkdir -p "$out"
"$mpirun" --allow-run-as-root --oversubscribe -np 2 "$shockgas" run "$scene" --out "$out/run" --no-plots \
  > "$out/stdout" 2> "$out/stderr" &
launcher=$!
# rank 1: the process whose environment says OMPI_COMM_WORLD_RANK=1
victim=""
for attempt in $(seq 1 100); do
  for pid in $(pgrep -f "$scene"); do
    if tr '\0' '\n' < /proc/$pid/environ 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=1"; then victim=$pid; fi
  done
  [ -n "$victim" ] && break
  sleep 0.1
done
[ -n "$victim" ] || { echo "rank 1 not found"; kill "$launcher"; exit 1; }
sleep 1.5  # inside its first realization
kill -9 "$victim"
wait "$launcher"
status=$?
cat "$out/stderr"
[ "$status" -ne 0 ] || { echo "the job did not fail"; exit 1; }
grep -q "shockgas: run failed: rank 1 stopped while running realization [0-9]" "$out/stderr" ||
  { echo "no shockgas message naming rank 1 and its realization"; exit 1; }
[ "$(grep -c '^shockgas:' "$out/stderr")" -eq 1 ] || { echo "not one shockgas message"; exit 1; }
[ ! -e "$out/run/result.h5" ] && [ ! -e "$out/run/summary.json" ] || { echo "a result was written"; exit 1; }
echo "rank 1 killed: the job stopped with one message and no result"
