#!/bin/sh
# The scene run by one process and by an MPI job of RANKS ranks: every dataset
# and summary figure agrees bit for bit (compare_runs), and the job's summaries
# record its ranks. SAID: a line the job must print on stderr, if given.
# usage: same_as_one_process.sh SHOCKGAS COMPARE_RUNS MPIRUN RANKS SCENE OUT [SAID]
set -eu
shockgas=$1 compare=$2 mpirun=$3 ranks=$4 scene=$5 out=$6 said=${7:-}
rm -rf "$out"
mkdir -p "$out"
"$shockgas" run "$scene" --out "$out/one" --quiet --no-plots
"$mpirun" --allow-run-as-root --oversubscribe -np "$ranks" "$shockgas" run "$scene" --out "$out/mpi" --quiet \
  --no-plots 2> "$out/mpi.stderr" || { cat "$out/mpi.stderr"; exit 1; }
cat "$out/mpi.stderr"
if [ -n "$said" ]; then grep -qF "$said" "$out/mpi.stderr" || { echo "not said: $said"; exit 1; }; fi
"$compare" "$out/one" "$out/mpi"
grep -rq "\"ranks\": $ranks" "$out/mpi" --include=summary.json || { echo "parallel.ranks = $ranks not recorded"; exit 1; }
