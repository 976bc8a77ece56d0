#!/bin/sh
# A run stopped by SIGNAL after its first checkpoint (KILL; or TERM: it writes
# one more and exits with status 128 + 15), then `shockgas run --resume`, equals the
# uninterrupted run bit for bit (compare_runs); the resumed run says how many
# realizations it kept, and removes the checkpoint once the result is written.
# ARGS... (optional) go to both runs, e.g. `--realizations 1:5` for a shard.
# SAID (environment, optional): what the resumed run must say; SAID_STOPPED
# (optional): what the run stopped by SIGTERM must say.
# usage: stopped_then_resumed.sh SHOCKGAS COMPARE_RUNS SCENE OUT SIGNAL [ARGS...]
set -eu
shockgas=$1 compare=$2 scene=$3 out=$4 signal=$5
shift 5
fail() { echo "$*"; exit 1; }
rm -rf "$out"
mkdir -p "$out"
# Checkpoints every 0.06 s (as soon as a realization finished), the interval
# recorded with the scene's overrides by both runs.
every="output.checkpoint_minutes=0.001"
"$shockgas" run "$scene" --out "$out/whole" --quiet --no-plots --set $every "$@"

# The stopped run: it stops itself (SIGSTOP, shockgas/app/files/fault.hpp) right after its
# first checkpoint is written, so the signal comes after that checkpoint and
# before the run's end however loaded the machine; then it continues to meet it.
SHOCKGAS_FAULT=checkpoint:stop "$shockgas" run "$scene" --out "$out/stopped" --quiet --no-plots --set $every "$@" \
  2> "$out/stopped.stderr" &
pid=$!
waited=0
until ps -o stat= -p $pid | grep -q '^T'; do
  sleep 0.05; waited=$((waited + 1))
  [ $waited -lt 1200 ] || fail "the run did not reach its first checkpoint within 60 s"
done
kill -s "$signal" $pid
kill -s CONT $pid 2> /dev/null || true  # a killed run is gone already
status=0
wait $pid || status=$?
cat "$out/stopped.stderr"
[ ! -f "$out/stopped/result.h5" ] || fail "the run ended before the signal: make the scene longer"
[ -f "$out/stopped/checkpoint.bin" ] || fail "no checkpoint after SIG$signal"
if [ "$signal" = TERM ]; then
  [ $status -eq 143 ] || fail "SIGTERM: exit status $status, not 143"
  grep -q "checkpoint written" "$out/stopped.stderr" || fail "SIGTERM: no 'checkpoint written' said"
  ls "$out/stopped" | grep -q partial && fail "temporary files left: $(ls "$out/stopped")"
  [ -z "${SAID_STOPPED:-}" ] || grep -q "$SAID_STOPPED" "$out/stopped.stderr" || fail "SIGTERM: no '$SAID_STOPPED' said"
fi

"$shockgas" run --resume "$out/stopped" --no-plots 2> "$out/resumed.stderr" || { cat "$out/resumed.stderr"; exit 1; }
cat "$out/resumed.stderr"
grep -q "realizations kept from the checkpoint" "$out/resumed.stderr" || fail "the resumed run kept nothing"
[ -z "${SAID:-}" ] || grep -q "$SAID" "$out/resumed.stderr" || fail "the resumed run did not say '$SAID'"
[ ! -f "$out/stopped/checkpoint.bin" ] || fail "the checkpoint is left after the result was written"
"$compare" "$out/whole" "$out/stopped"
