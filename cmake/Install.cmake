# `cmake --install`: the command, one shared library with the facade's headers,
# the CMake package and the pkg-config file, the plots, scenes and docs, the man
# page. Components: cli (the command and what it reads), lib (the shared
# library), dev (headers, CMake package, pkg-config), python (python/CMakeLists.txt).
# Nothing installed names a source or build path (test install.no_build_paths).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
include(${CMAKE_CURRENT_LIST_DIR}/PublicHeaders.cmake)

# --- The library: every module's objects in one libshockgas.so.MAJOR.MINOR -------
set(shockgas_modules shockgas_core shockgas_particles shockgas_continuum shockgas_compare shockgas_studies
                     shockgas_app)
# They go into shared objects (this library, the Python module): position-independent
# code, without semantic interposition (calls inside a library stay direct and
# inlinable, as in the command).
foreach(module ${shockgas_modules})
  set_target_properties(${module} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${module} PRIVATE -fno-semantic-interposition)
  endif()
endforeach()
add_library(shockgas_library SHARED ${PROJECT_SOURCE_DIR}/shockgas/library_version.cpp)
foreach(module ${shockgas_modules})
  target_sources(shockgas_library PRIVATE $<TARGET_OBJECTS:${module}>)
endforeach()
# For the modules' own libraries (HDF5, FFTW, ...): the archives add no object twice.
target_link_libraries(shockgas_library PRIVATE ${shockgas_modules})
target_include_directories(shockgas_library PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                           $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/generated>
                           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
target_compile_features(shockgas_library PUBLIC cxx_std_20)
# 0.x: a minor version may change the interface, so the SONAME carries it.
set(SHOCKGAS_SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
set_target_properties(shockgas_library PROPERTIES OUTPUT_NAME shockgas EXPORT_NAME shockgas
                      VERSION ${PROJECT_VERSION} SOVERSION ${SHOCKGAS_SOVERSION}
                      LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/lib)
add_library(shockgas::shockgas ALIAS shockgas_library)

install(TARGETS shockgas RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cli)
install(TARGETS shockgas_library EXPORT shockgasTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT lib NAMELINK_COMPONENT dev)
foreach(header ${SHOCKGAS_PUBLIC_HEADERS})
  get_filename_component(dir ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${dir} COMPONENT dev)
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/generated/shockgas/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shockgas COMPONENT dev)

# --- find_package(shockgas) and pkg-config --------------------------------------
set(SHOCKGAS_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/shockgas)
install(EXPORT shockgasTargets NAMESPACE shockgas:: DESTINATION ${SHOCKGAS_CMAKE_DIR} COMPONENT dev)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/install/shockgasConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/install/shockgasConfig.cmake
                              INSTALL_DESTINATION ${SHOCKGAS_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/install/shockgasConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/install/shockgasConfig.cmake
              ${PROJECT_BINARY_DIR}/install/shockgasConfigVersion.cmake
        DESTINATION ${SHOCKGAS_CMAKE_DIR} COMPONENT dev)
# The .pc file finds its prefix from its own place (${pcfiledir}): a moved prefix still works.
file(RELATIVE_PATH SHOCKGAS_PC_TO_PREFIX /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
configure_file(${CMAKE_CURRENT_LIST_DIR}/install/shockgas.pc.in ${PROJECT_BINARY_DIR}/install/shockgas.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/install/shockgas.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
        COMPONENT dev)

# --- What the command reads: share/shockgas (shockgas/app/files/data_dir.hpp) ------
# The build tree has the same layout as links into the sources, so that build/shockgas
# finds them as an installed command does.
set(SHOCKGAS_DATA_SOURCES plots=plots scenes=data/scenes)
# Installs them under DESTINATION (relative to the prefix) as COMPONENT; links
# them under LINK_DIR for the build tree.
function(shockgas_data destination component link_dir)
  file(MAKE_DIRECTORY ${link_dir})
  foreach(entry ${SHOCKGAS_DATA_SOURCES})
    string(REPLACE "=" ";" pair ${entry})
    list(GET pair 0 name)
    list(GET pair 1 source)
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${source} ${link_dir}/${name} SYMBOLIC)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${source}/ DESTINATION ${destination}/${name} COMPONENT ${component}
            PATTERN __pycache__ EXCLUDE PATTERN "*.pyc" EXCLUDE)
  endforeach()
endfunction()
shockgas_data(${CMAKE_INSTALL_DATADIR}/shockgas cli ${PROJECT_BINARY_DIR}/share/shockgas)
install(FILES README.md CHANGELOG.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT cli)
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT cli)

# --- The man page, from the command's own --help (help2man) -------------------------
find_program(SHOCKGAS_HELP2MAN help2man)
if(SHOCKGAS_HELP2MAN)
  set(man_page ${PROJECT_BINARY_DIR}/man/shockgas.1)
  add_custom_command(OUTPUT ${man_page}
                     COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
                     COMMAND ${SHOCKGAS_HELP2MAN} --no-info --no-discard-stderr
                             --name "particle gas and inviscid Burgers equation side by side"
                             --output ${man_page} $<TARGET_FILE:shockgas>
                     DEPENDS shockgas VERBATIM)
  add_custom_target(shockgas_man ALL DEPENDS ${man_page})
  install(FILES ${man_page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT cli)
else()
  message(NOTICE "shockgas: no man page -- help2man not found (Debian package 'help2man', or run scripts/setup)")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/Package.cmake)
