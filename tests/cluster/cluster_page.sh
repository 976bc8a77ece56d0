#!/bin/sh
# The batch scripts of docs/cluster.md, run as the page gives them under a fake
# Slurm on this machine (fake-slurm/: sbatch runs a job at once, srun runs its
# tasks with mpirun), in a directory laid out as the scripts expect: build/shockgas
# is this build, data/scenes/paper/fig4.toml a small stand-in for the paper's
# scene (the same sweep of three r at sizes of seconds). What each case checks:
#   mpi      mpi.sbatch: an MPI job of several ranks (3 on this machine) writes the
#            result of one process, bit for bit (compare_runs);
#   array    submit.sh: the job array of shards.sbatch, then merge.sbatch once the
#            array succeeded: the merged result equals one process's;
#   preempt  preemptible.sbatch stopped by the SIGTERM of its time limit (to every
#            task of its job step) after the first checkpoint asks to be requeued
#            (scontrol requeue), and submitted again, resumes and ends with one
#            process's result.
# usage: cluster_page.sh SHOCKGAS COMPARE_RUNS MPIRUN PAGE STAND_IN OUT CASE
set -eu
shockgas=$1 compare=$2 mpirun=$3 page=$4 stand_in=$5 out=$6 case=$7
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "$*"; exit 1; }
rm -rf "$out"
mkdir -p "$out/build" "$out/data/scenes/paper"
ln -s "$shockgas" "$out/build/shockgas"
cp "$stand_in" "$out/data/scenes/paper/fig4.toml"
cd "$out"
export PATH="$here/fake-slurm:$PATH" FAKE_SLURM_STATE="$out/slurm" FAKE_MPIRUN="$mpirun"
script() { sh "$here/page_script.sh" "$page" "$1" > "$1" || fail "the page has no script '# $1:'"; }
logs() { for f in *.log slurm-*.out; do [ -f "$f" ] && { echo "== $f"; cat "$f"; }; done; true; }
same_as_one_process() {  # THREADS: the thread count the scripts set
  build/shockgas run data/scenes/paper/fig4.toml --out reference --quiet --set particles.threads=$1
  "$compare" reference results/fig4
}

case $case in
  mpi)
    script mpi.sbatch
    sbatch mpi.sbatch || { logs; fail "mpi.sbatch failed"; }
    logs
    grep -q '"ranks": 3' results/fig4/summary.json || fail "not a job of 3 ranks"
    same_as_one_process "$(sed -n 's/^#SBATCH --cpus-per-task=\([0-9]*\).*/\1/p' mpi.sbatch)"
    ;;
  array)
    script shards.sbatch
    script merge.sbatch
    script submit.sh
    bash submit.sh || { logs; fail "submit.sh failed"; }
    logs
    [ "$(ls -d shards/fig4/* | wc -l)" -eq 10 ] || fail "not 10 shards: $(ls shards/fig4)"
    same_as_one_process "$(sed -n 's/^#SBATCH --cpus-per-task=\([0-9]*\).*/\1/p' shards.sbatch)"
    ;;
  preempt)
    script preemptible.sbatch
    # The job's rank 0 stops itself (SIGSTOP, shockgas/app/files/fault.hpp) right after its first
    # checkpoint, so that the signal comes before the job's end however fast.
    SHOCKGAS_FAULT=checkpoint:stop sbatch preemptible.sbatch > first.out 2>&1 &
    job=$!
    stopped() {  # a stopped task of the job step: a child of the step's mpirun
      for srun in $(cat slurm/srun.pids 2> /dev/null); do
        for pid in $(pgrep -P "$(pgrep -P $srun)"); do
          if ps -o stat= -p $pid | grep -q '^T'; then echo $pid; fi
        done
      done
    }
    waited=0
    until root=$(stopped) && [ -n "$root" ]; do
      sleep 0.05; waited=$((waited + 1))
      [ $waited -lt 1200 ] || { kill $job; logs; fail "no checkpoint within 60 s"; }
    done
    kill -s TERM $(cat slurm/srun.pids)  # the time limit's SIGTERM (--signal) to the job step's tasks
    term_pending() { [ $(($(printf '%d' 0x$(awk '/^ShdPnd/ {print $2}' /proc/$root/status)) & (1 << 14))) -ne 0 ]; }
    waited=0
    until term_pending; do
      sleep 0.05; waited=$((waited + 1))
      [ $waited -lt 200 ] || fail "rank 0 got no SIGTERM within 10 s"
    done
    kill -s CONT $root
    wait $job && { logs; fail "the stopped job succeeded: make the stand-in longer"; }
    [ -f results/fig4/checkpoint.bin ] && [ ! -f results/fig4/result.h5 ] || { logs; fail "no checkpoint kept"; }
    [ -s slurm/requeued ] || { logs; fail "the stopped job did not go back to the queue"; }
    : > slurm/requeued
    sbatch preemptible.sbatch || { logs; fail "the requeued job failed"; }
    logs
    [ ! -s slurm/requeued ] || fail "the finished job asked to be requeued"
    grep -q "realizations kept from the checkpoint" *.log || fail "the requeued job did not resume"
    same_as_one_process "$(sed -n 's/^#SBATCH --cpus-per-task=\([0-9]*\).*/\1/p' preemptible.sbatch)"
    ;;
  *) fail "unknown case $case" ;;
esac
echo "docs/cluster.md, $case: the page's scripts ran and wrote the result of one process"
