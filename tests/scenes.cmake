# Scenes as regression tests: each scene with a stored expectation in
# data/scenes/expected/<name>.json is run by the command and its summary.json
# checked (tests/tools/check_summary.py), and every theory its report.md and
# summary.json state held against the laws the expectation lists as holding for
# the scene (tests/tools/check_report_theories.py). Label `scene`, or `slow` for the
# expectations under data/scenes/expected/slow/. The teaching gallery
# (data/scenes/gallery/, expectations in data/scenes/expected/gallery/) is
# labelled `scene` too, and each of its tests fails beyond 3x the scene's
# stated expected_runtime.
find_program(SHOCKGAS_PYTHON NAMES python3 REQUIRED)

# shockgas_scene_test(scene_file expected label [NAME test_name] [TIMEOUT seconds])
function(shockgas_scene_test scene_file expected label)
  cmake_parse_arguments(ARG "" "NAME;TIMEOUT" "" ${ARGN})
  get_filename_component(name ${expected} NAME_WE)
  if(ARG_NAME)
    set(name ${ARG_NAME})
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 1800)
  endif()
  set(out ${PROJECT_BINARY_DIR}/scene-tests/${name})
  add_test(NAME scene.${name}
           COMMAND sh -c "rm -rf '${out}' && '$<TARGET_FILE:shockgas>' run '${scene_file}' --out '${out}' --quiet --no-plots && '${SHOCKGAS_PYTHON}' '${PROJECT_SOURCE_DIR}/tests/tools/check_summary.py' '${expected}' '${out}' && '${SHOCKGAS_PYTHON}' '${PROJECT_SOURCE_DIR}/tests/tools/check_report_theories.py' '${expected}' '${out}'"
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(scene.${name} PROPERTIES LABELS ${label} TIMEOUT ${ARG_TIMEOUT})
endfunction()

file(GLOB expectations CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/data/scenes/expected/*.json)
foreach(expected ${expectations})
  get_filename_component(name ${expected} NAME_WE)
  shockgas_scene_test(${PROJECT_SOURCE_DIR}/data/scenes/${name}.toml ${expected} scene)
endforeach()

file(GLOB slow_expectations CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/data/scenes/expected/slow/*.json)
foreach(expected ${slow_expectations})
  get_filename_component(name ${expected} NAME_WE)
  # data/scenes/expected/slow/paper-fig1-small.json -> data/scenes/paper/fig1-small.toml
  string(REGEX REPLACE "^paper-" "paper/" scene_path ${name})
  shockgas_scene_test(${PROJECT_SOURCE_DIR}/data/scenes/${scene_path}.toml ${expected} slow)
endforeach()

file(GLOB gallery_expectations CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/data/scenes/expected/gallery/*.json)
foreach(expected ${gallery_expectations})
  get_filename_component(name ${expected} NAME_WE)
  set(scene ${PROJECT_SOURCE_DIR}/data/scenes/gallery/${name}.toml)
  file(STRINGS ${scene} runtime REGEX "^expected_runtime")
  if(NOT runtime MATCHES "\"([0-9]+) s\"")
    message(FATAL_ERROR "${scene}: expected_runtime must read \"<seconds> s\" (the test fails beyond 3x it)")
  endif()
  math(EXPR timeout "3 * ${CMAKE_MATCH_1}")
  shockgas_scene_test(${scene} ${expected} scene NAME gallery.${name} TIMEOUT ${timeout})
endforeach()
