# MPI is optional: with it, `mpirun -np K shockgas run` spreads an ensemble's
# realizations over K ranks (docs/cluster.md); without it shockgas runs as one
# process, and shards and `shockgas merge` still work. Open MPI from Debian:
# libopenmpi-dev and openmpi-bin (scripts/setup installs them).
option(SHOCKGAS_MPI "Build the MPI ensembles when MPI is found" ON)
set(SHOCKGAS_WITH_MPI OFF)
if(SHOCKGAS_MPI)
  find_package(MPI QUIET COMPONENTS CXX)
  find_program(SHOCKGAS_MPIRUN NAMES mpirun)
  if(MPI_CXX_FOUND)
    set(SHOCKGAS_WITH_MPI ON)
    message(STATUS "shockgas: MPI found (MPI ${MPI_CXX_VERSION}, ${SHOCKGAS_MPIRUN}): ensembles run on the ranks of an MPI job")
  else()
    message(STATUS "shockgas: MPI not found -- built for one process (install the Debian packages 'libopenmpi-dev openmpi-bin' for MPI)")
  endif()
else()
  message(STATUS "shockgas: MPI off (-DSHOCKGAS_MPI=OFF) -- built for one process")
endif()
