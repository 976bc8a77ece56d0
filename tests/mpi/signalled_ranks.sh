#!/bin/sh
# A job whose ranks get a signal while they run realizations stops with one
# shockgas message (beside the launcher's) and writes no result: SIGKILL to
# rank 1 (killed, its node lost) names the rank and its realization; SIGTERM to
# every rank (a scheduler's pre-emption) is an interruption.
# usage: signalled_ranks.sh SHOCKGAS MPIRUN SCENE OUT SIGNAL RANKS MESSAGE
#   RANKS: the ranks signalled ("1", "0 1"); MESSAGE: the line expected (a grep pattern)
set -u
shockgas=$1 mpirun=$2 scene=$3 out=$4 signal=$5 ranks=$6 message=$7
rm -rf "$out"
mkdir -p "$out"
"$mpirun" --allow-run-as-root --oversubscribe -np 2 "$shockgas" run "$scene" --out "$out/run" --no-plots \
  > "$out/stdout" 2> "$out/stderr" &
launcher=$!
rank_pid() {  # the launcher's child whose environment says OMPI_COMM_WORLD_RANK=$1 (not
  # another job's rank: a test running beside this one may launch the same scene)
  for pid in $(pgrep -P $launcher); do
    if tr '\0' '\n' < /proc/$pid/environ 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$1"; then echo "$pid"; fi
  done
}
pids=""
for rank in $ranks; do
  pid=""
  for attempt in $(seq 1 100); do
    pid=$(rank_pid "$rank")
    [ -n "$pid" ] && break
    sleep 0.1
  done
  [ -n "$pid" ] || { echo "rank $rank not found"; kill "$launcher"; exit 1; }
  pids="$pids $pid"
done
sleep 2.5  # inside the first realizations (long.toml: 4 a rank, a few seconds each)
kill -s "$signal" $pids
wait "$launcher"
status=$?
cat "$out/stderr"
[ "$status" -ne 0 ] || { echo "the job did not fail"; exit 1; }
grep -q "$message" "$out/stderr" || { echo "no line: $message"; exit 1; }
[ "$(grep -c '^shockgas:' "$out/stderr")" -eq 1 ] || { echo "not one shockgas message"; exit 1; }
[ ! -e "$out/run/result.h5" ] && [ ! -e "$out/run/summary.json" ] || { echo "a result was written"; exit 1; }
echo "signal $signal to rank(s) $ranks: the job stopped with one message and no result"
