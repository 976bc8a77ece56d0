# The MPI tests (label `mpi`):
# `mpirun -np K shockgas run` on a small ensemble and a small sweep, with 2 and
# with 3 ranks (3 ranks on this 2-core machine: --oversubscribe), each result
# compared bit for bit with the one-process run; more ranks than realizations;
# a rank killed during a run; every rank interrupted. A sanitizer build leaves
# them out: AddressSanitizer's leak report at exit flags Open MPI's own
# allocations in every rank, and mpirun then fails the job for that. (The rank-0
# protocol is tested without MPI in test_job_ensembles, which the sanitizers run.)
add_executable(compare_runs tools/compare_runs.cpp)
target_link_libraries(compare_runs PRIVATE shockgas_app)
target_include_directories(compare_runs PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})

if(NOT SHOCKGAS_WITH_MPI OR NOT SHOCKGAS_MPIRUN)
  message(STATUS "shockgas: the MPI tests are skipped (shockgas built without MPI, or no mpirun)")
  return()
endif()
if(SHOCKGAS_SANITIZE)
  message(STATUS "shockgas: the MPI tests are left out of a sanitizer build (SHOCKGAS_SANITIZE=ON)")
  return()
endif()

set(mpi_dir ${CMAKE_CURRENT_SOURCE_DIR}/mpi)
function(shockgas_mpi_test name)
  add_test(NAME mpi.${name} COMMAND ${ARGN})
  set_tests_properties(mpi.${name} PROPERTIES LABELS mpi TIMEOUT 600)
endfunction()

foreach(ranks 2 3)
  foreach(scene ensemble sweep)
    shockgas_mpi_test(${scene}_${ranks}_ranks sh ${mpi_dir}/same_as_one_process.sh $<TARGET_FILE:shockgas>
                      $<TARGET_FILE:compare_runs> ${SHOCKGAS_MPIRUN} ${ranks} ${mpi_dir}/${scene}.toml
                      ${PROJECT_BINARY_DIR}/mpi-tests/${scene}_${ranks})
  endforeach()
endforeach()
shockgas_mpi_test(more_ranks_than_realizations sh ${mpi_dir}/same_as_one_process.sh $<TARGET_FILE:shockgas>
                  $<TARGET_FILE:compare_runs> ${SHOCKGAS_MPIRUN} 3 ${mpi_dir}/few.toml
                  ${PROJECT_BINARY_DIR}/mpi-tests/few "note: 3 ranks for 2 realizations: rank 2 has none to run")
shockgas_mpi_test(killed_rank sh ${mpi_dir}/signalled_ranks.sh $<TARGET_FILE:shockgas> ${SHOCKGAS_MPIRUN}
                  ${mpi_dir}/long.toml ${PROJECT_BINARY_DIR}/mpi-tests/killed KILL 1
                  "^shockgas: run failed: rank 1 stopped while running realization [0-9]")
shockgas_mpi_test(interrupted_job sh ${mpi_dir}/signalled_ranks.sh $<TARGET_FILE:shockgas> ${SHOCKGAS_MPIRUN}
                  ${mpi_dir}/long.toml ${PROJECT_BINARY_DIR}/mpi-tests/interrupted TERM "0 1"
                  "^shockgas: .*interrupted by signal 15")

# Checkpoints of a job (stopped_job_resumed.sh): a 2-rank job stopped by SIGTERM
# to rank 0 (rank 0 writes a checkpoint) or by SIGKILL of mpirun and the ranks
# after the first periodic checkpoint, then resumed with 2 and 3 ranks and as
# one process; and a one-process checkpoint resumed by a job of 2 ranks. Each
# equals the one-process run bit for bit.
foreach(signal TERM KILL)
  set(scene ${mpi_dir}/checkpoint.toml)
  if(signal STREQUAL TERM)
    set(scene ${mpi_dir}/checkpoint-long.toml)  # a realization outlasts a checkpoint interval: see the file
  endif()
  shockgas_mpi_test(checkpoint_resumed_after_${signal} sh ${mpi_dir}/stopped_job_resumed.sh $<TARGET_FILE:shockgas>
                    $<TARGET_FILE:compare_runs> ${SHOCKGAS_MPIRUN} ${scene}
                    ${PROJECT_BINARY_DIR}/mpi-tests/checkpoint-${signal} 2 ${signal} 2 3 1)
endforeach()
shockgas_mpi_test(one_process_checkpoint_resumed sh ${mpi_dir}/stopped_job_resumed.sh $<TARGET_FILE:shockgas>
                  $<TARGET_FILE:compare_runs> ${SHOCKGAS_MPIRUN} ${mpi_dir}/checkpoint.toml
                  ${PROJECT_BINARY_DIR}/mpi-tests/checkpoint-one 1 TERM 2)

# The states of running realizations in a job (running_states_resumed.sh): a
# 2-rank job of 2 long realizations stopped by SIGKILL or SIGTERM after both
# ranks saved a state, resumed with 2 ranks and as one process, equals the
# one-process run bit for bit; with rank 1's state damaged, the resumed job
# exits 2 (bad input, as one process) and writes nothing.
foreach(signal KILL TERM)
  shockgas_mpi_test(running_states_resumed_after_${signal} sh ${mpi_dir}/running_states_resumed.sh
                    $<TARGET_FILE:shockgas> $<TARGET_FILE:compare_runs> ${SHOCKGAS_MPIRUN} ${mpi_dir}/running.toml
                    ${PROJECT_BINARY_DIR}/mpi-tests/running-${signal} ${signal})
endforeach()
