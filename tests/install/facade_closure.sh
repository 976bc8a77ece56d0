#!/bin/sh
# The installed headers are exactly the facade and what it reaches: none missing
# (a program could not compile) and none more (an internal header made public),
# and they are the list cmake/PublicHeaders.cmake declares.
# usage: facade_closure.sh CXX PREFIX "DECLARED HEADERS"
set -eu
cxx=$1 prefix=$2 declared=$3
inc="$prefix/include"
tmp=$(mktemp -d) && trap 'rm -rf "$tmp"' EXIT
cd "$tmp"  # nothing but the prefix to include from
echo '#include "shockgas/shockgas.hpp"' | "$cxx" -std=c++20 -I "$inc" -x c++ -M - |
  tr ' \\' '\n\n' | grep "^$inc/shockgas/" | sed "s|^$inc/||" | sort -u > "$tmp/reached"
(cd "$inc" && find shockgas -type f | sort) > "$tmp/installed"
printf '%s\n' $declared shockgas/version.hpp | sort > "$tmp/declared"
status=0
diff -u "$tmp/reached" "$tmp/installed" || { echo "the facade reaches (-) / installed (+) differ"; status=1; }
diff -u "$tmp/declared" "$tmp/installed" || { echo "declared (-) / installed (+) differ"; status=1; }
echo "$(wc -l < "$tmp/installed") public headers"
exit $status
