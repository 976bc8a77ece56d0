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

# One CTest test per file, plots.NAME for tests/scripts/test_NAME.py, so that
# `ctest -j` runs them side by side. The files below draw a whole run in each
# of their tests (about 7 CPU-seconds a drawing): each of their tests is a CTest
# test of its own, plots.NAME.TEST, selected by its pytest node id.
set(plots_split_by_test drawing)
set(plots_dir ${PROJECT_SOURCE_DIR}/tests/scripts)
function(shockgas_plot_test name node)
  add_test(NAME ${name} COMMAND /usr/bin/python3 -m pytest -q -p no:cacheprovider ${node}
           WORKING_DIRECTORY ${PROJECT_BINARY_DIR})
  set_tests_properties(${name} PROPERTIES LABELS unit TIMEOUT 600
                       ENVIRONMENT "SHOCKGAS=$<TARGET_FILE:shockgas>;MPLBACKEND=Agg")
endfunction()

file(GLOB plot_test_files CONFIGURE_DEPENDS ${plots_dir}/test_*.py)
foreach(file ${plot_test_files})
  get_filename_component(name ${file} NAME_WE)
  string(REGEX REPLACE "^test_" "" name ${name})
  if(NOT name IN_LIST plots_split_by_test)
    shockgas_plot_test(plots.${name} ${file})
    continue()
  endif()
  # Its test functions, read again whenever the file changes.
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${file})
  file(STRINGS ${file} functions REGEX "^def test_[A-Za-z0-9_]*\\(")
  if(NOT functions)
    message(FATAL_ERROR "${file}: no test function found to split the file by")
  endif()
  foreach(line ${functions})
    string(REGEX REPLACE "^def (test_[A-Za-z0-9_]*)\\(.*" "\\1" function "${line}")
    string(REGEX REPLACE "^test_" "" case ${function})
    shockgas_plot_test(plots.${name}.${case} ${file}::${function})
  endforeach()
endforeach()
