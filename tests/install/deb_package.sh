#!/bin/sh
# The Debian package: built by cpack, its dependencies from dpkg-shlibdeps,
# extracted into an empty root (not installed), where its command says its
# version and runs a small scene with the scenes and plots it carries.
# Then the containers of packaging/ are checked against the packages folder.
# usage: deb_package.sh CPACK BUILD_DIR PACKAGING_DIR
set -eu
cpack=$1 build=$2 packaging=$3
command -v dpkg-deb >/dev/null || { echo "skipped: not a Debian system (no dpkg-deb)"; exit 77; }
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
(cd "$build" && "$cpack" -G DEB -B "$work/packages" > "$work/cpack.log") || { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/packages/*.deb)
echo "$(basename "$deb"): $(du -k "$deb" | cut -f1) kB"
dpkg-deb -f "$deb" Package Version Depends
dpkg-deb -f "$deb" Depends | grep -q libhdf5 || { echo "no dependency on HDF5's library found"; exit 1; }
dpkg-deb -x "$deb" "$work/root"
bin="$work/root/usr/bin/shockgas"
"$bin" --version
"$bin" run "$work/root/usr/share/shockgas/scenes/gallery/riemann.toml" --out "$work/run" -q --no-plots
"$bin" info "$work/run" | head -2
python3 "$(dirname "$0")/check_containers.py" "$packaging" "$work/packages"
