#!/usr/bin/env bash
# The exact hull as a whole command against the least such a process must do
# (docs/performance/command.md, "The hull command"): `shockgas run` of the sticky
# gas (r = 0, solver = "hull", one sample at T, the defaults otherwise, no plots)
# against bench/plain_pav_command, which draws the same bodies and makes one
# plain pool-adjacent-violators pass. Runs them in turn (A B A B ...), each a fresh
# process timed by /usr/bin/time, and prints each pair's wall and CPU (user +
# system) seconds, peak memory and the ratios command / plain, then the medians.
#
# Usage: bench/hull_command.sh [--build-dir DIR] [--N N] [--t T] [--pairs K]
#   defaults: build, N = 1e7, T = 1000, 5 pairs
set -euo pipefail
self=$(realpath "$0")
build=build N=1e7 T=1000 pairs=5
while [ $# -gt 0 ]; do
  case $1 in
    --build-dir) build=${2:?}; shift ;;
    --N) N=${2:?}; shift ;;
    --t) T=${2:?}; shift ;;
    --pairs) pairs=${2:?}; shift ;;
    -h | --help) sed -n '2,11p' "$self"; exit 0 ;;
    *) echo "hull_command.sh: unknown option $1 (allowed: --build-dir, --N, --t, --pairs)" >&2; exit 2 ;;
  esac
  shift
done
cd "$(dirname "$self")/.."
command=$build/shockgas plain=$build/bench/plain_pav_command
for f in /usr/bin/time "$command" "$plain"; do
  [ -x "$f" ] || { echo "hull_command.sh: $f is missing (build the targets shockgas and plain_pav_command)" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '[initial]\nN = %s\nseed = 1\n[particles]\nr = 0\nsolver = "hull"\nt_end = %s\nsamples = 1\n' "$N" "$T" \
  > "$work/hull.toml"

# wall, CPU seconds and peak KiB of one run
timed() { /usr/bin/time -f '%e %U %S %M' -o "$work/time" "$@" > /dev/null 2>&1; awk '{print $1, $2 + $3, $4}' "$work/time"; }

echo "host: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg); N = $N, t = $T"
echo "pair  command: wall cpu KiB   plain: wall cpu KiB   ratio wall cpu"
for k in $(seq "$pairs"); do
  read -r aw ac am < <(timed "$command" run "$work/hull.toml" --out "$work/out" --force -q --no-plots)
  read -r bw bc bm < <(timed "$plain" "$N" "$T" 1)
  printf '%s  %s %s %s   %s %s %s   %.2f %.2f\n' "$k" "$aw" "$ac" "$am" "$bw" "$bc" "$bm" \
    "$(echo "$aw / $bw" | bc -l)" "$(echo "$ac / $bc" | bc -l)"
done | tee "$work/pairs"
sort -n -k8 "$work/pairs" | awk '{w[NR] = $8} END {printf "median ratio, wall: %.2f\n", w[int((NR + 1) / 2)]}'
sort -n -k9 "$work/pairs" | awk '{c[NR] = $9} END {printf "median ratio, CPU: %.2f\n", c[int((NR + 1) / 2)]}'
