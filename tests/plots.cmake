# The pictures of plots/plot_result.py (plots/shockplot/), and the scripts of
# scripts/paper/: small scenes run by the command and their figures inspected
# with pytest (tests/scripts/).
# Label `unit`. Skipped with a message where /usr/bin/python3 lacks pytest,
# matplotlib, h5py or numpy (scripts/setup installs them).
execute_process(COMMAND /usr/bin/python3 -c "import pytest, matplotlib, h5py, numpy"
                RESULT_VARIABLE shockgas_plot_tests_missing OUTPUT_QUIET ERROR_QUIET)
if(NOT shockgas_plot_tests_missing EQUAL 0)
  message(STATUS "plot tests skipped: /usr/bin/python3 lacks pytest, matplotlib, h5py or numpy (run scripts/setup)")
  return()
endif()
add_test(NAME plots.pictures
         COMMAND /usr/bin/python3 -m pytest -q -p no:cacheprovider ${PROJECT_SOURCE_DIR}/tests/scripts
         WORKING_DIRECTORY ${PROJECT_BINARY_DIR})
set_tests_properties(plots.pictures PROPERTIES LABELS unit TIMEOUT 600
                     ENVIRONMENT "SHOCKGAS=$<TARGET_FILE:shockgas>;MPLBACKEND=Agg")
