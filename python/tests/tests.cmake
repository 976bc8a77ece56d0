# The Python module's tests (pytest, from Debian's python3-pytest), one CTest
# test per file, label `python` (part of the default `-LE slow` run). Skipped
# with a message where numpy, pytest or h5py are missing for the target Python.
execute_process(COMMAND ${Python_EXECUTABLE} -c "import numpy, pytest, h5py" RESULT_VARIABLE missing
                OUTPUT_QUIET ERROR_QUIET)
if(missing)
  message(NOTICE "shockgas: Python tests skipped -- ${Python_EXECUTABLE} lacks numpy, pytest or h5py: install "
                 "the Debian packages 'python3-numpy python3-pytest python3-h5py' (or run scripts/setup)")
  return()
endif()
file(GLOB python_tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/tests/test_*.py)
foreach(file ${python_tests})
  get_filename_component(name ${file} NAME_WE)
  string(REGEX REPLACE "^test_" "" name ${name})
  add_test(NAME python.${name}
           COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${file}
           WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/tests)
  set_tests_properties(python.${name} PROPERTIES LABELS python TIMEOUT 600
                       ENVIRONMENT "PYTHONPATH=${PROJECT_BINARY_DIR}/python;SHOCKGAS_BUILD_DIR=${PROJECT_BINARY_DIR}")
endforeach()
