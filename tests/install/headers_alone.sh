#!/bin/sh
# Every installed header of one module compiles on its own, from the prefix only:
# each includes what it uses.
# usage: headers_alone.sh CXX PREFIX MODULE
set -eu
cxx=$1 prefix=$2 module=$3
inc="$prefix/include"
count=0
cd /  # nothing but the prefix to include from
for header in $(cd "$inc" && find "shockgas/$module" -name '*.hpp' | sort); do
  echo "#include \"$header\"" | "$cxx" -std=c++20 -I "$inc" -x c++ -fsyntax-only - ||
    { echo "$header does not compile alone"; exit 1; }
  count=$((count + 1))
done
echo "$count headers of shockgas/$module compile alone"
[ "$count" -gt 0 ]
