# The batch scripts of docs/cluster.md, run as the page gives them under a
# stand-in for Slurm on this machine, each result compared bit for bit with one
# process's (tests/cluster/cluster_page.sh): the job array of shards with its
# merge step (label `unit`); the MPI job and the pre-emptible job that requeues
# itself and resumes (label `mpi`: they need mpirun, and are left out of a
# sanitizer build as the MPI tests are, tests/mpi.cmake).
set(cluster_dir ${CMAKE_CURRENT_SOURCE_DIR}/cluster)
function(shockgas_cluster_page_test case label)
  add_test(NAME cluster_page.${case}
           COMMAND sh ${cluster_dir}/cluster_page.sh $<TARGET_FILE:shockgas> $<TARGET_FILE:compare_runs>
                   "${SHOCKGAS_MPIRUN}" ${PROJECT_SOURCE_DIR}/docs/cluster.md ${cluster_dir}/fig4-stand-in.toml
                   ${PROJECT_BINARY_DIR}/cluster-page-tests/${case} ${case})
  set_tests_properties(cluster_page.${case} PROPERTIES LABELS ${label} TIMEOUT 600)
endfunction()

shockgas_cluster_page_test(array unit)
if(SHOCKGAS_WITH_MPI AND SHOCKGAS_MPIRUN AND NOT SHOCKGAS_SANITIZE)
  shockgas_cluster_page_test(mpi mpi)
  shockgas_cluster_page_test(preempt mpi)
else()
  message(STATUS "shockgas: the MPI scripts of docs/cluster.md are not tested (no MPI, or a sanitizer build)")
endif()
