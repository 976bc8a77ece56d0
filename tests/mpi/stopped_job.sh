# Sourced by the tests of stopped jobs (stopped_job_resumed.sh,
# running_states_resumed.sh): the end of a job stopped by a signal.
#
# SIGTERM goes to the ranks, never to mpirun (as srun signals every task), and
# mpirun keeps its default odls_base_sigkill_timeout (1 s). Open MPI 4.1's
# mpirun, signalled itself, continues its ranks, sleeps that timeout, forwards
# SIGTERM (a second SIGTERM ends a rank at once), sleeps it again and sends
# SIGKILL: counted from the signal, a rank of a loaded machine may need longer
# to save, and mpirun sleeps out both however soon its ranks are done (at 30 s,
# a minute per test). Unsignalled, it starts to end the ranks only once rank 0
# ends the job (MPI_Abort) with every state and the checkpoint saved and said:
# nothing is cut off, and the job ends about a second after the signal.
#
# await_stopped_job LAUNCHER OUT SIGNAL: waits for the launcher, then for every
# process of the job in OUT/stopped (none may go on writing into the
# directory), prints what the job said and fails unless it ended without a
# result, with a checkpoint and with a non-zero status: after SIGTERM 143, the
# signal's, as one process ends (a job script requeues on a status over 128).
# Needs fail().
await_stopped_job() {
  status=0
  wait "$1" || status=$?
  waited=0
  while pgrep -f "$2/stopped" > /dev/null; do
    sleep 0.1; waited=$((waited + 1))
    [ $waited -lt 300 ] || fail "ranks of the stopped job still run 30 s after the launcher ended"
  done
  cat "$2/stopped.stderr"
  [ $status -ne 0 ] || fail "the stopped job exited with status 0"
  [ "$3" != TERM ] || [ $status -eq 143 ] || fail "SIGTERM: the stopped job exited with status $status, not 143"
  [ ! -f "$2/stopped/result.h5" ] || fail "the job ended before the signal: make the scene longer"
  [ -f "$2/stopped/checkpoint.bin" ] || fail "no checkpoint after SIG$3"
}
