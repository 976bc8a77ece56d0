# Scenes as regression tests: each scene with a stored expectation in
# data/scenes/expected/<name>.json is run by the command and its summary.json
# checked (scripts/check_summary.py). Label `scene`, or `slow` for the
# expectations under data/scenes/expected/slow/.
find_program(SHOCKGAS_PYTHON NAMES python3 REQUIRED)

function(shockgas_scene_test scene_file expected label)
  get_filename_component(name ${expected} NAME_WE)
  set(out ${PROJECT_BINARY_DIR}/scene-tests/${name})
  add_test(NAME scene.${name}
           COMMAND sh -c "rm -rf '${out}' && '$<TARGET_FILE:shockgas>' run '${scene_file}' --out '${out}' --quiet --no-plots && '${SHOCKGAS_PYTHON}' '${PROJECT_SOURCE_DIR}/scripts/check_summary.py' '${expected}' '${out}/summary.json'"
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(scene.${name} PROPERTIES LABELS ${label} TIMEOUT 1800)
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
