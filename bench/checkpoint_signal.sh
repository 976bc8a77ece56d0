#!/bin/sh
# SIGTERM to exit of one long realization that keeps checkpoints: the run is
# signalled WAIT seconds in, reaches its next safe point, writes its state
# (run_state_file.hpp) and exits with 143. Prints the time from the signal to
# the exit, the state file's size and what the run said.
#
# usage: checkpoint_signal.sh SHOCKGAS N WAIT OUT [THREADS]
#   e.g. bench/checkpoint_signal.sh build/shockgas 100000000 120 /tmp/ckpt-1e8
set -eu
shockgas=$1 n=$2 wait=$3 out=$4 threads=${5:-2}
rm -rf "$out"
mkdir -p "$out"
cat > "$out/scene.toml" <<SCENE
[scene]
name = "checkpoint-signal"
[initial]
N = $n
[particles]
r = 0.9
delta = 1e-2
t_end = 1e5
realizations = 1
threads = $threads
[output]
plots = false
checkpoint_minutes = 0
SCENE
"$shockgas" run "$out/scene.toml" --out "$out/run" --quiet --no-plots 2> "$out/stderr" &
pid=$!
sleep "$wait"
start=$(date +%s.%N)
kill -TERM $pid
status=0
wait $pid || status=$?
end=$(date +%s.%N)
echo "N = $n: SIGTERM after $wait s, exit status $status after $(echo "$end - $start" | bc) s"
ls -l "$out/run" | grep checkpoint || true
grep -v "^particles:" "$out/stderr" || true
