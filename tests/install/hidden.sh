# Sourced by the relocation tests. run_hidden SOURCE BUILD COMMAND: runs COMMAND
# (a shell line) with the source and build trees hidden behind empty mounts in a
# private mount namespace, where the system allows one (root); else as it is,
# and says so.
run_hidden() {
  if unshare -m true 2>/dev/null; then
    unshare -m sh -c "mount -t tmpfs none '$1' && { [ ! -d '$2' ] || mount -t tmpfs none '$2'; } && \
[ ! -e '$1/CMakeLists.txt' ] && $3"
    echo "ran with $1 and $2 hidden"
  else
    sh -c "$3"
    echo "ran with the sources still visible (no private mount namespace here)"
  fi
}
