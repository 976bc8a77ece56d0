#!/usr/bin/env bash
# The three waits of a newcomer (docs/performance.md, "First contact"), measured
# on this checkout in a fresh build directory, as a fresh clone would meet them:
#
#   1. configure and build the command alone (Release, no compiler cache), as
#      scripts/quickstart does;
#   2. the default scene with its plots, as the quickstart's last step;
#   3. build everything else, then the README's default test set
#      (ctest -LE slow -j2), as README's test command does after the quickstart.
#
# Each step is timed as a whole process (wall, and user + system CPU of it and its
# children). Prints one Markdown table row per step with the date, the host's
# processor, its cores and its load average when the step started (a shared
# machine's figures say little without it); --append adds the rows to the table
# in docs/performance.md. Packages are not installed here (scripts/setup: apt's
# time depends on the mirror).
#
# Usage: bench/first_contact.sh [--append] [--build-dir DIR] [--keep]
#   --build-dir DIR  where to build (default: a new build-first-contact-PID in the checkout)
#   --keep           keep the build directory afterwards
set -euo pipefail
self=$(realpath "$0")

append=false keep=false build=""
while [ $# -gt 0 ]; do
  case $1 in
    --append) append=true ;;
    --keep) keep=true ;;
    --build-dir) build=$(realpath -m "${2:?first_contact.sh: --build-dir needs a directory}"); shift ;;
    -h | --help) sed -n '2,20p' "$self"; exit 0 ;;
    *) echo "first_contact.sh: unknown option $1 (allowed: --append, --keep, --build-dir DIR)" >&2; exit 2 ;;
  esac
  shift
done
cd "$(dirname "$self")/.."
[ -x /usr/bin/time ] || { echo "first_contact.sh: needs /usr/bin/time (Debian package time)" >&2; exit 2; }
if [ -z "$build" ]; then
  # In the checkout with the usual permissions, as a clone's build/ (tests run
  # the command as another user: mktemp's private directory would refuse them).
  build=$PWD/build-first-contact-$$
  mkdir -m 755 "$build"
elif [ -e "$build" ] && [ -n "$(ls -A "$build")" ]; then
  echo "first_contact.sh: --build-dir $build is not empty (allowed: a new or empty directory)" >&2
  exit 2
fi
out=$(mktemp -d /tmp/shockgas-first-contact-run.XXXXXX)
cleanup() {
  rm -rf "$out"
  $keep || rm -rf "$build"
}
trap cleanup EXIT

export CCACHE_DISABLE=1  # a fresh clone has no cache
cores=$(nproc)
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
day=$(date -u +%Y-%m-%d)
rows=()

# step NAME COMMAND...: runs it, timed by /usr/bin/time, and keeps its row.
step() {
  local name=$1 load times
  shift
  load=$(cut -d' ' -f1 /proc/loadavg)
  times=$(mktemp)
  if ! /usr/bin/time -f '%e %U %S' -o "$times" "$@"; then
    echo "first_contact.sh: step \"$name\" failed: $*" >&2
    exit 1
  fi
  read -r wall user sys <"$times"
  rm -f "$times"
  rows+=("| $name | $(awk -v w="$wall" 'BEGIN { printf "%.0f", w }') s | $(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.0f", u + s }') s | $day, $cpu, $cores cores, load $load at the start |")
  echo "first_contact.sh: $name: $wall s wall, $user s user + $sys s system" >&2
}

step "configure + build of the command (Release, no compiler cache)" \
  bash -c 'cmake -S . -B "$1" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER= \
    -DCMAKE_C_COMPILER_LAUNCHER= >/dev/null && cmake --build "$1" -j"$2" --target shockgas >/dev/null' _ "$build" "$cores"
step "the default scene with its plots" "$build/shockgas" run data/scenes/default.toml --out "$out/default" -q
step "build of the rest (tests, benchmarks, Python, lab)" \
  bash -c 'cmake --build "$1" -j"$2" >/dev/null' _ "$build" "$cores"
step "the README's default test set (ctest -LE slow -j2)" \
  bash -c 'cd "$1" && ctest -LE slow -j2 >"$2" 2>&1 || { tail -30 "$2" >&2; exit 1; }' _ "$build" "$out/ctest.log"

printf '%s\n' "${rows[@]}"
if $append; then
  # The rows go first under the header of the table that follows the marker.
  marker="<!-- first_contact.sh rows -->"
  grep -qF "$marker" docs/performance.md || { echo "first_contact.sh: no '$marker' in docs/performance.md" >&2; exit 1; }
  printf '%s\n' "${rows[@]}" >"$out/rows"
  awk -v marker="$marker" -v rows="$out/rows" '
    { print }
    $0 == marker { armed = 1; next }
    armed && /^\|---/ { while ((getline line < rows) > 0) print line; armed = 0; done = 1 }
    END { if (!done) exit 1 }
  ' docs/performance.md >"$out/performance.md" || { echo "first_contact.sh: no table under the marker" >&2; exit 1; }
  cp "$out/performance.md" docs/performance.md
  echo "first_contact.sh: rows added to the table under the marker in docs/performance.md" >&2
fi
