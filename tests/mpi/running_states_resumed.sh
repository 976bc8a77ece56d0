#!/bin/sh
# A job of 2 ranks, each running one realization, stopped by SIGNAL after both
# ranks saved a state of their realization (checkpoint.run-0-K.bin, one per
# realization, in the shared directory), then resumed as a job of 2 ranks and as
# one process: each resumed run says both realizations continue from their
# states, and ends with the result of one uninterrupted process, bit for bit
# (compare_runs). Then, with realization 1's state damaged, a resumed job of 2
# ranks exits 2 and writes nothing.
#   SIGNAL: KILL to the launcher and every rank (a lost node), or TERM to every
#     rank (a scheduler's pre-emption, as srun signals every task: every rank
#     saves again and rank 0 says so).
# usage: running_states_resumed.sh SHOCKGAS COMPARE_RUNS MPIRUN SCENE OUT SIGNAL
set -eu
shockgas=$1 compare=$2 mpirun=$3 scene=$4 out=$5 signal=$6
fail() { echo "$*"; exit 1; }
. "$(dirname "$0")/stopped_job.sh"
rm -rf "$out"
mkdir -p "$out"
# States every 0.06 s of a realization's run, the interval recorded with the
# scene's overrides by every run.
every="output.checkpoint_minutes=0.001"
"$shockgas" run "$scene" --out "$out/whole" --quiet --no-plots --set $every

# Each rank stops itself (SIGSTOP, shockgas/app/files/fault.hpp) right after its first state
# is written (fault point "checkpoint" on rank 0, "state" on rank 1), so the
# signal comes after both ranks saved and before the end.
args="run $scene --out $out/stopped --quiet --no-plots --set $every"
"$mpirun" --allow-run-as-root --oversubscribe -np 1 env SHOCKGAS_FAULT=checkpoint:stop "$shockgas" $args : \
  -np 1 env SHOCKGAS_FAULT=state:stop "$shockgas" $args 2> "$out/stopped.stderr" &
launcher=$!
ranks_stopped() {  # both ranks, the launcher's children, stopped
  n=0
  for pid in $(pgrep -P $launcher); do
    if ps -o stat= -p $pid | grep -q '^T'; then n=$((n + 1)); fi
  done
  [ $n -eq 2 ]
}
waited=0
until ranks_stopped; do
  sleep 0.05; waited=$((waited + 1))
  [ $waited -lt 1200 ] || { kill -s KILL $launcher $(pgrep -P $launcher); fail "the ranks did not both save a state within 60 s"; }
done
ranks=$(pgrep -P $launcher)
if [ "$signal" = KILL ]; then
  kill -s KILL $launcher $ranks
else
  # Every rank, not the launcher (stopped_job.sh): the signal is pending while
  # a rank is stopped and acts as it continues.
  kill -s "$signal" $ranks
  kill -s CONT $ranks
fi
await_stopped_job $launcher "$out" "$signal"
for k in 0 1; do
  [ -f "$out/stopped/checkpoint.run-0-$k.bin" ] || fail "no state of realization $k: $(ls "$out/stopped")"
done
if [ "$signal" = TERM ]; then
  grep -q "realization 0 saved at t = .*realization 1 saved at t = " "$out/stopped.stderr" ||
    fail "SIGTERM: not said that both realizations saved their states"
fi

for ranks in 2 1; do
  resumed="$out/resumed-$ranks"
  cp -r "$out/stopped" "$resumed"
  if [ $ranks = 1 ]; then
    "$shockgas" run --resume "$resumed" --no-plots 2> "$out/resumed-$ranks.stderr" ||
      { cat "$out/resumed-$ranks.stderr"; fail "the resumed process failed"; }
  else
    "$mpirun" --allow-run-as-root --oversubscribe -np $ranks "$shockgas" run --resume "$resumed" --no-plots \
      2> "$out/resumed-$ranks.stderr" || { cat "$out/resumed-$ranks.stderr"; fail "the resumed job of $ranks failed"; }
  fi
  cat "$out/resumed-$ranks.stderr"
  grep -q "0 of 2 realizations kept from the checkpoint, 2 continue from a saved state" "$out/resumed-$ranks.stderr" ||
    fail "$ranks: did not continue both realizations from their states"
  [ ! -f "$resumed/checkpoint.bin" ] || fail "$ranks: the checkpoint is left after the result was written"
  ls "$resumed" | grep -q "checkpoint.run-" && fail "$ranks: states left after the result was written"
  "$compare" "$out/whole" "$resumed"
done

# Realization 1's state damaged (a byte in its middle): the job of 2 ranks
# stops as one process does on bad input, with exit 2, naming the file: rank 0
# checks every state before it deals any realization out, so none continues
# (one that did would move its states file on); the damaged state and the
# checkpoint are left as they were and no result is written.
damaged="$out/damaged"
cp -r "$out/stopped" "$damaged"
state="$damaged/checkpoint.run-0-1.bin"
size=$(wc -c < "$state")
byte=$(dd if="$state" bs=1 skip=$((size / 2)) count=1 2>/dev/null | od -An -tu1 | tr -d ' ')
printf "\\$(printf %o $(((byte + 1) % 256)))" | dd of="$state" bs=1 seek=$((size / 2)) conv=notrunc 2>/dev/null
listing() { md5sum "$state" "$damaged/checkpoint.bin"; }
before=$(listing)
code=0
"$mpirun" --allow-run-as-root --oversubscribe -np 2 "$shockgas" run --resume "$damaged" --no-plots \
  2> "$out/damaged.stderr" || code=$?
cat "$out/damaged.stderr"
[ $code -eq 2 ] || fail "a damaged state on rank 1: exit $code, not 2 (bad input)"
grep -q "^shockgas: error: .*checkpoint.run-0-1.bin.*damaged" "$out/damaged.stderr" ||
  fail "a damaged state on rank 1: not named"
[ "$(listing)" = "$before" ] || fail "a damaged state on rank 1: the state or the checkpoint changed"
[ ! -f "$damaged/result.h5" ] || fail "a damaged state on rank 1: a result was written"
echo "stopped on 2 ranks by SIG$signal with both realizations' states saved, resumed on 2 ranks and 1: the uninterrupted result, bit for bit; a damaged state on rank 1: exit 2, nothing written"
