# The installed shockgas as a user meets it (label `install`, part of the default
# `ctest -LE slow`): `cmake --install` into a prefix, then from that prefix only:
# no build or source path inside, every public header compiling alone, a program
# of one's own built with find_package and with pkg-config, the command and the
# Python module run with plots after the prefix is moved and the sources and the
# build are hidden (tests/install/*.sh).
set(install_dir ${PROJECT_BINARY_DIR}/install-tests)
set(install_scripts ${CMAKE_CURRENT_SOURCE_DIR}/install)
include(${PROJECT_SOURCE_DIR}/cmake/PublicHeaders.cmake)

add_test(NAME install.prefix
         COMMAND sh -c "rm -rf '${install_dir}/prefix' && '${CMAKE_COMMAND}' --install '${PROJECT_BINARY_DIR}' \
--prefix '${install_dir}/prefix' > '${install_dir}.log'")
set_tests_properties(install.prefix PROPERTIES FIXTURES_SETUP installed)

add_test(NAME install.no_build_paths
         COMMAND sh ${install_scripts}/no_build_paths.sh ${install_dir}/prefix ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
string(REPLACE ";" " " public_headers "${SHOCKGAS_PUBLIC_HEADERS}")
add_test(NAME install.facade_closure
         COMMAND sh ${install_scripts}/facade_closure.sh ${CMAKE_CXX_COMPILER} ${install_dir}/prefix "${public_headers}")
foreach(module core particles continuum compare app)
  add_test(NAME install.headers_alone_${module}
           COMMAND sh ${install_scripts}/headers_alone.sh ${CMAKE_CXX_COMPILER} ${install_dir}/prefix ${module})
endforeach()
add_test(NAME install.find_package_example
         COMMAND sh ${install_scripts}/find_package_example.sh ${CMAKE_COMMAND} ${install_dir}/prefix
                 ${PROJECT_SOURCE_DIR}/examples/cpp ${install_dir}/find-package)
add_test(NAME install.pkg_config_example
         COMMAND sh ${install_scripts}/pkg_config_example.sh ${CMAKE_CXX_COMPILER} ${install_dir}/prefix
                 ${PROJECT_SOURCE_DIR}/examples/cpp ${install_dir}/pkg-config)
set_tests_properties(install.no_build_paths install.facade_closure install.find_package_example
                     install.pkg_config_example PROPERTIES FIXTURES_REQUIRED installed)
foreach(module core particles continuum compare app)
  set_tests_properties(install.headers_alone_${module} PROPERTIES FIXTURES_REQUIRED installed)
endforeach()

# Moved and alone: each installs its own prefix (the other tests may still read theirs).
add_test(NAME install.relocated_command
         COMMAND sh ${install_scripts}/relocated_command.sh ${CMAKE_COMMAND} ${PROJECT_BINARY_DIR}
                 ${PROJECT_SOURCE_DIR})
add_test(NAME install.relocated_python
         COMMAND sh ${install_scripts}/relocated_python.sh ${CMAKE_COMMAND} ${PROJECT_BINARY_DIR}
                 ${PROJECT_SOURCE_DIR})

add_test(NAME install.wheel COMMAND sh ${install_scripts}/wheel.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
add_test(NAME install.deb COMMAND sh ${install_scripts}/deb_package.sh ${CMAKE_CPACK_COMMAND} ${PROJECT_BINARY_DIR}
                                 ${PROJECT_SOURCE_DIR}/packaging)

get_property(install_tests DIRECTORY PROPERTY TESTS)
list(FILTER install_tests INCLUDE REGEX "^install\\.")
set_tests_properties(${install_tests} PROPERTIES LABELS install SKIP_RETURN_CODE 77 TIMEOUT 300)
# cpack first brings `all` up to date (its preinstall step), then installs the
# components cli, lib and dev file by file, packs, compresses and runs
# dpkg-shlibdeps: about 25 CPU-seconds, most of them the file system's, so the
# .deb is labelled `slow` as well. The files it holds are those of the same
# install rules and components that the default set checks from a prefix
# (install.prefix and the tests on it, install.relocated_command); what only
# install.deb checks is cpack's package itself: its Depends (libhdf5 found by
# dpkg-shlibdeps), the command run from the extracted root, and the containers
# of packaging/ against the package's name.
set_tests_properties(install.deb PROPERTIES LABELS "install;slow" TIMEOUT 900)
