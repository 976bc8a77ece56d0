#!/bin/sh
# No installed binary, library or module names the source or the build tree:
# what it reads it finds from its own place (shockgas/app/files/data_dir.hpp).
# usage: no_build_paths.sh PREFIX SOURCE_DIR BUILD_DIR
set -eu
prefix=$1 source=$2 build=$3
command -v strings >/dev/null || { echo "skipped: no strings (Debian package binutils)"; exit 77; }
found=0 checked=0
for file in $(find "$prefix" -type f \( -perm -u+x -o -name '*.so*' \)); do
  checked=$((checked + 1))
  for path in "$source" "$build"; do
    if strings -a "$file" | grep -F -q "$path"; then
      echo "$file names $path:"; strings -a "$file" | grep -F "$path" | head -3
      found=1
    fi
  done
done
echo "$checked installed binaries and libraries checked"
[ "$checked" -gt 0 ] || { echo "nothing installed to check in $prefix"; exit 1; }
exit $found
