# The lab (docs/gallery.md, "The lab"): the page of `shockgas lab`, where the
# library's engine, hull and Hopf-Lax solution run live in a browser, compiled
# to WebAssembly by Debian's emscripten (lab/CMakeLists.txt). Optional: without
# its tools the rest builds as before and `shockgas lab` says what is missing.
# Never on the way to the command itself: the target `lab` is built by `all`.
option(SHOCKGAS_BUILD_LAB "Build the lab's page (needs emscripten, node-acorn, python3)" ON)
find_program(SHOCKGAS_EMXX em++)
find_program(SHOCKGAS_NODE NAMES node nodejs)
set(SHOCKGAS_LAB_MISSING "")
if(NOT SHOCKGAS_BUILD_LAB)
  set(SHOCKGAS_LAB_MISSING "it was switched off when shockgas was configured (-DSHOCKGAS_BUILD_LAB=OFF)")
elseif(NOT SHOCKGAS_EMXX OR NOT EXISTS "${SHOCKGAS_EMXX}")
  set(SHOCKGAS_LAB_MISSING "em++ was not found: install the Debian package 'emscripten'")
elseif(NOT SHOCKGAS_NODE)
  set(SHOCKGAS_LAB_MISSING "node was not found (Emscripten runs it): install the Debian package 'nodejs'")
elseif(NOT EXISTS /usr/share/nodejs/acorn)
  set(SHOCKGAS_LAB_MISSING "Emscripten's JavaScript optimiser needs acorn: install the Debian package 'node-acorn'")
elseif(NOT EXISTS /usr/bin/python3)
  set(SHOCKGAS_LAB_MISSING "/usr/bin/python3 (3.11 or later: tomllib) was not found: install the Debian package 'python3'")
endif()
# Where the page is written in the build tree (beside the links of cmake/Install.cmake:
# the command finds it as it finds its plots).
include(GNUInstallDirs)
set(SHOCKGAS_LAB_BUILD_DIR ${PROJECT_BINARY_DIR}/share/shockgas/lab)
if(SHOCKGAS_LAB_MISSING)
  message(STATUS "shockgas lab: not built: ${SHOCKGAS_LAB_MISSING}")
else()
  message(STATUS "shockgas lab: built by `all` into ${SHOCKGAS_LAB_BUILD_DIR} (${SHOCKGAS_EMXX})")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/lab_files.hpp.in ${PROJECT_BINARY_DIR}/generated/shockgas/lab_files.hpp
               @ONLY)
