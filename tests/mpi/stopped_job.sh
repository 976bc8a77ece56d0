# Sourced by the tests of stopped jobs (stopped_job_resumed.sh,
# running_states_resumed.sh): the end of a job stopped by a signal.
# await_stopped_job LAUNCHER OUT SIGNAL: waits for the launcher, then for every
# process of the job in OUT/stopped (none may go on writing into the
# directory), prints what the job said and fails unless it ended with a
# non-zero status, without a result and with a checkpoint. Needs fail().
await_stopped_job() {
  status=0
  wait "$1" || status=$?
  waited=0
  while pgrep -f "$2/stopped" > /dev/null; do
    sleep 0.1; waited=$((waited + 1))
    [ $waited -lt 300 ] || fail "ranks of the stopped job still run 30 s after SIG$3 to the launcher"
  done
  cat "$2/stopped.stderr"
  [ $status -ne 0 ] || fail "the stopped job exited with status 0"
  [ ! -f "$2/stopped/result.h5" ] || fail "the job ended before the signal: make the scene longer"
  [ -f "$2/stopped/checkpoint.bin" ] || fail "no checkpoint after SIG$3"
}
