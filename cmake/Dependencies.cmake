# Every external library comes from a Debian package. A missing one stops the
# configure step with one line naming the package; `scripts/setup` installs them all.
find_package(PkgConfig QUIET)
if(NOT PkgConfig_FOUND)
  message(NOTICE "shockgas: pkg-config not found -- install the Debian package 'pkg-config' (or run scripts/setup)")
  message(FATAL_ERROR "missing dependency: pkg-config")
endif()

# One unwrapped line naming the package, then the stop.
function(shockgas_missing what package)
  message(NOTICE "shockgas: ${what} not found -- install the Debian package '${package}' (or run scripts/setup)")
  message(FATAL_ERROR "missing dependency: ${package}")
endfunction()

pkg_check_modules(FFTW3 QUIET IMPORTED_TARGET fftw3)
if(NOT FFTW3_FOUND)
  shockgas_missing("FFTW3" "libfftw3-dev")
endif()

pkg_check_modules(HDF5 QUIET IMPORTED_TARGET hdf5-serial)
if(NOT HDF5_FOUND)
  shockgas_missing("HDF5 (serial)" "libhdf5-dev")
endif()

pkg_check_modules(MUPARSER QUIET IMPORTED_TARGET muparser)
if(NOT MUPARSER_FOUND)
  shockgas_missing("muParser" "libmuparser-dev")
endif()

pkg_check_modules(TOMLPP QUIET IMPORTED_TARGET tomlplusplus)
if(NOT TOMLPP_FOUND)
  shockgas_missing("toml++" "libtomlplusplus-dev")
endif()

find_package(Eigen3 3.3 QUIET NO_MODULE)
if(NOT Eigen3_FOUND)
  shockgas_missing("Eigen3" "libeigen3-dev")
endif()

# Boost's header-only sorts (the random initial positions: shockgas/core/initial_stream.cpp).
find_package(Boost 1.71 QUIET)
if(NOT Boost_FOUND)
  shockgas_missing("Boost headers" "libboost-dev")
endif()

find_package(CLI11 QUIET CONFIG)
if(NOT CLI11_FOUND)
  shockgas_missing("CLI11" "libcli11-dev")
endif()

find_package(nlohmann_json 3 QUIET CONFIG)
if(NOT nlohmann_json_FOUND)
  shockgas_missing("nlohmann-json" "nlohmann-json3-dev")
endif()

# SUNDIALS: the Debian package's CMake config lists targets for libraries it does
# not ship, so the serial libraries are found one by one.
find_path(SUNDIALS_INCLUDE_DIR cvode/cvode.h)
set(SUNDIALS_LIBRARIES "")
foreach(lib sundials_cvode sundials_arkode sundials_nvecserial sundials_sunmatrixband
            sundials_sunlinsolband sundials_sunlinsolspgmr sundials_sunmatrixdense
            sundials_sunlinsoldense)
  find_library(SUNDIALS_${lib}_LIBRARY ${lib})
  if(NOT SUNDIALS_${lib}_LIBRARY)
    shockgas_missing("SUNDIALS library ${lib}" "libsundials-dev")
  endif()
  list(APPEND SUNDIALS_LIBRARIES ${SUNDIALS_${lib}_LIBRARY})
endforeach()
if(NOT SUNDIALS_INCLUDE_DIR)
  shockgas_missing("SUNDIALS headers" "libsundials-dev")
endif()
add_library(shockgas_sundials INTERFACE)
target_include_directories(shockgas_sundials SYSTEM INTERFACE ${SUNDIALS_INCLUDE_DIR})
target_link_libraries(shockgas_sundials INTERFACE ${SUNDIALS_LIBRARIES})

# SHA-256 of the result files (shockgas/app/files/sha256.cpp): OpenSSL's libcrypto.
find_package(OpenSSL QUIET COMPONENTS Crypto)
if(NOT OpenSSL_FOUND)
  shockgas_missing("OpenSSL libcrypto" "libssl-dev")
endif()

find_package(Threads REQUIRED)

# The tests and benchmarks are optional parts: the command builds without them
# (scripts/quickstart installs only what it needs), and says what is missing.
set(SHOCKGAS_TESTS_MISSING "")
if(SHOCKGAS_BUILD_TESTS)
  find_package(GTest QUIET)
  if(GTest_FOUND)
    include(GoogleTest)
  else()
    set(SHOCKGAS_TESTS_MISSING "GoogleTest was not found (Debian package 'libgtest-dev')")
    message(WARNING "shockgas: the tests are not built: ${SHOCKGAS_TESTS_MISSING}; "
                    "scripts/setup installs it, then configure again (cmake -B build)")
    set(SHOCKGAS_BUILD_TESTS OFF)
  endif()
endif()
if(SHOCKGAS_BUILD_BENCH)
  find_package(benchmark QUIET)
  if(NOT benchmark_FOUND)
    message(STATUS "shockgas: the benchmarks are not built: Google Benchmark was not found "
                   "(Debian package 'libbenchmark-dev'; scripts/setup installs it)")
    set(SHOCKGAS_BUILD_BENCH OFF)
  endif()
endif()

# One source list per library: every .cpp in the folder.
function(shockgas_library name dir)
  file(GLOB sources CONFIGURE_DEPENDS ${dir}/*.cpp)
  add_library(${name} STATIC ${sources})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/generated)
endfunction()
