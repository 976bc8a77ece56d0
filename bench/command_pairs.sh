#!/usr/bin/env bash
# The whole `shockgas run` command against another build of it on the same scene
# (docs/performance/command.md): the two run in turn (A B A B ...), each a fresh
# process timed by /usr/bin/time, output and files included; prints each pair's
# wall, user and system seconds, peak memory and the ratio A / B of wall time,
# then the medians. Pairing keeps a ratio meaningful while a shared host's speed
# drifts; quote the median.
#
# Usage: bench/command_pairs.sh --baseline SHOCKGAS [--build-dir DIR] [--scene FILE]
#                               [--pairs K] [--fresh-dirs]
#   A: DIR/shockgas (default build/shockgas); B: the baseline executable.
#   scene: default N = 1e7, r = 0.9, delta = 1e-2, t_end = 10, one thread.
#   Each command writes into its own directory, replaced at every run as a user
#   re-running it would; --fresh-dirs gives every run a new one (nothing deleted
#   while the pairs run). Default 9 pairs.
set -euo pipefail
self=$(realpath "$0")
build=build baseline='' scene='' pairs=9 fresh=0
while [ $# -gt 0 ]; do
  case $1 in
    --baseline) baseline=${2:?}; shift ;;
    --build-dir) build=${2:?}; shift ;;
    --scene) scene=$(realpath "${2:?}"); shift ;;
    --pairs) pairs=${2:?}; shift ;;
    --fresh-dirs) fresh=1 ;;
    -h | --help) sed -n '2,15p' "$self"; exit 0 ;;
    *) echo "command_pairs.sh: unknown option $1 (allowed: --baseline, --build-dir, --scene, --pairs, --fresh-dirs)" >&2
       exit 2 ;;
  esac
  shift
done
[ -n "$baseline" ] || { echo "command_pairs.sh: --baseline SHOCKGAS is required (the build to compare with)" >&2; exit 2; }
baseline=$(realpath "$baseline")
cd "$(dirname "$self")/.."
command=$(realpath "$build/shockgas")
for f in /usr/bin/time "$command" "$baseline"; do
  [ -x "$f" ] || { echo "command_pairs.sh: $f is missing or not executable" >&2; exit 2; }
done
case $pairs in '' | *[!0-9]* | 0) echo "command_pairs.sh: --pairs $pairs: a whole number >= 1" >&2; exit 2 ;; esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ -z "$scene" ]; then
  scene=$work/n7.toml
  printf '[initial]\nN = 10000000\nseed = 1\n[particles]\nr = 0.9\ndelta = 1e-2\nt_end = 10\nthreads = 1\n' > "$scene"
fi

# wall, user, system seconds and peak KiB of one run of shockgas $1 into $2
timed() {
  /usr/bin/time -f '%e %U %S %M' -o "$work/time" "$1" run "$scene" --out "$2" -q --no-plots > /dev/null 2>&1 ||
    { echo "command_pairs.sh: $1 run $scene failed" >&2; exit 1; }
  cat "$work/time"
}
out() { if [ "$fresh" = 1 ]; then mktemp -d "$work/$1.XXXXXX"; else echo "$work/$1"; fi; }

echo "host: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
echo "A = $command"
echo "B = $baseline"
echo "scene: $scene; $([ "$fresh" = 1 ] && echo 'a new directory each run' || echo 'each command re-runs into its own directory')"
echo "pair  A: wall user sys KiB   B: wall user sys KiB   A/B wall"
for k in $(seq "$pairs"); do
  a=$(timed "$command" "$(out a)") || exit 1
  b=$(timed "$baseline" "$(out b)") || exit 1
  read -r aw au as am <<< "$a"
  read -r bw bu bs bm <<< "$b"
  printf '%s  %s %s %s %s   %s %s %s %s   %.3f\n' "$k" "$aw" "$au" "$as" "$am" "$bw" "$bu" "$bs" "$bm" \
    "$(echo "$aw / $bw" | bc -l)" | tee -a "$work/pairs"
done
median() { sort -n -k"$1" "$work/pairs" | awk -v c="$1" '{v[NR] = $c} END {print v[int((NR + 1) / 2)]}'; }
printf 'median: A wall %s s (user %s, sys %s), B wall %s s (user %s, sys %s); A/B wall %s, rate %.2fx\n' \
  "$(median 2)" "$(median 3)" "$(median 4)" "$(median 6)" "$(median 7)" "$(median 8)" "$(median 10)" \
  "$(echo "1 / $(median 10)" | bc -l)"
