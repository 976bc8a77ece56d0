#!/bin/sh
# A job stopped after its first periodic checkpoint, then resumed with other
# numbers of ranks, ends with the result of one uninterrupted process, bit for
# bit (compare_runs):
#   STOP_RANKS: the ranks of the stopped job (1: one process, without mpirun);
#   SIGNAL: TERM to rank 0 (it tells the other ranks to save, writes one more
#     checkpoint and says so in one message, and the job fails) or KILL to the
#     launcher and every rank (a lost node: the job ends without a word; the
#     periodic checkpoint is what is left);
#   RESUME_RANKS: the resumed jobs, each from a copy of the stopped directory
#     (1: `shockgas run --resume` without mpirun).
# Every resumed job says how many realizations it kept and removes the
# checkpoint once the result is written.
# usage: stopped_job_resumed.sh SHOCKGAS COMPARE_RUNS MPIRUN SCENE OUT STOP_RANKS SIGNAL RESUME_RANKS...
set -eu
shockgas=$1 compare=$2 mpirun=$3 scene=$4 out=$5 stop_ranks=$6 signal=$7
shift 7
fail() { echo "$*"; exit 1; }
. "$(dirname "$0")/stopped_job.sh"
rm -rf "$out"
mkdir -p "$out"
# Checkpoints every 0.06 s (as soon as a realization finished), the interval
# recorded with the scene's overrides by every run.
every="output.checkpoint_minutes=0.001"
launch() {  # RANKS ARGS...: shockgas as one process or as a job of RANKS ranks (in a subshell: exec)
  ranks=$1
  shift
  if [ "$ranks" = 1 ]; then
    exec "$shockgas" "$@"
  else
    exec "$mpirun" --allow-run-as-root --oversubscribe -np "$ranks" "$shockgas" "$@"
  fi
}
"$shockgas" run "$scene" --out "$out/whole" --quiet --no-plots --set $every

# The stopped job: rank 0 stops itself (SIGSTOP, shockgas/app/files/fault.hpp) right after its
# first checkpoint is written, so the signal comes after that checkpoint and
# before the job's end however loaded the machine; then it continues to meet it.
(export SHOCKGAS_FAULT=checkpoint:stop; launch "$stop_ranks" run "$scene" --out "$out/stopped" --quiet --no-plots \
  --set $every) 2> "$out/stopped.stderr" &
launcher=$!
rank_0() {  # the process of rank 0: the launcher's child whose environment says so, or the one process
  if [ "$stop_ranks" = 1 ]; then echo $launcher; return; fi
  for pid in $(pgrep -P $launcher); do
    if tr '\0' '\n' < /proc/$pid/environ 2> /dev/null | grep -qx "OMPI_COMM_WORLD_RANK=0"; then echo $pid; fi
  done
}
waited=0
until root=$(rank_0) && [ -n "$root" ] && ps -o stat= -p $root | grep -q '^T'; do
  sleep 0.05; waited=$((waited + 1))
  [ $waited -lt 1200 ] || { kill $launcher; fail "rank 0 did not reach its first checkpoint within 60 s"; }
done
if [ "$signal" = KILL ]; then
  kill -s KILL $launcher $(pgrep -P $launcher)  # the whole job at once, as a lost node or `scancel -s KILL`
else
  # Rank 0 alone, not the launcher (stopped_job.sh): the signal is pending
  # while rank 0 is stopped and acts as it continues; the other ranks hear of
  # it from rank 0.
  kill -s "$signal" $root
  kill -s CONT $root
fi
await_stopped_job $launcher "$out" "$signal"
if [ "$signal" = TERM ]; then
  grep -q "^shockgas: interrupted by signal 15 (SIGTERM); checkpoint written: " "$out/stopped.stderr" ||
    fail "SIGTERM: not said that a checkpoint was written"
  [ "$(grep -c '^shockgas:' "$out/stopped.stderr")" -eq 1 ] || fail "SIGTERM: not one shockgas message"
  ls "$out/stopped" | grep -q partial && fail "temporary files left: $(ls "$out/stopped")"
fi

for ranks in "$@"; do
  resumed="$out/resumed-$ranks"
  cp -r "$out/stopped" "$resumed"
  (launch "$ranks" run --resume "$resumed" --no-plots) 2> "$out/resumed-$ranks.stderr" ||
    { cat "$out/resumed-$ranks.stderr"; fail "the job of $ranks resumed failed"; }
  cat "$out/resumed-$ranks.stderr"
  grep -q "realizations kept from the checkpoint" "$out/resumed-$ranks.stderr" || fail "$ranks: kept nothing"
  [ ! -f "$resumed/checkpoint.bin" ] || fail "$ranks: the checkpoint is left after the result was written"
  "$compare" "$out/whole" "$resumed"
done
echo "stopped on $stop_ranks rank(s) by SIG$signal, resumed on $* rank(s): the uninterrupted result, bit for bit"
