# The notebooks of notebooks/ (docs/teach.md), label `notebook`: each executed top to
# bottom by nbclient under the module's Python with PYTHONPATH at the build's module
# (tests/tools/run_notebook.py), failing on any cell that raises, the notebook's own
# asserts of its numbers among them; skipped with a message (exit 77) where the module
# was not built or Jupyter is missing. And the check that they are stored without
# outputs (any python3, no Jupyter needed). Included after python/, which defines the
# module's target.
set(notebook_dir ${PROJECT_SOURCE_DIR}/notebooks)
file(GLOB notebooks CONFIGURE_DEPENDS ${notebook_dir}/*.ipynb)
list(LENGTH notebooks notebook_count)

add_test(NAME notebook.stored_without_outputs
         COMMAND ${SHOCKGAS_PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/tools/check_notebooks_stripped.py
                 ${notebook_dir} 6)
set_tests_properties(notebook.stored_without_outputs PROPERTIES LABELS "notebook;unit" TIMEOUT 60)

foreach(notebook ${notebooks})
  get_filename_component(name ${notebook} NAME_WE)
  if(TARGET _shockgas)
    add_test(NAME notebook.${name}
             COMMAND ${SHOCKGAS_PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/tools/run_notebook.py ${notebook})
  else()
    add_test(NAME notebook.${name}
             COMMAND sh -c "echo 'skipped: the Python module was not built (cmake said why)'; exit 77")
  endif()
  # 60 s on two cores is each notebook's budget (docs/teach.md); twice it under load.
  set_tests_properties(notebook.${name} PROPERTIES LABELS notebook SKIP_RETURN_CODE 77 TIMEOUT 240
                       ENVIRONMENT "PYTHONPATH=${PROJECT_BINARY_DIR}/python")
endforeach()
