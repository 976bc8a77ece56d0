# The instruction set of the build (SHOCKGAS_NATIVE). ON (the default on x86-64
# where the compiler accepts -march=native): every file is compiled for the build
# machine's processor, so the engine's SIMD paths (AVX-512, AVX2) are used where
# it has them; the binary may then not start on an older processor. OFF: the
# compiler's portable default (baseline x86-64 on x86: SSE2).
#
# Either way -ffp-contract=off: a multiply and an add are never fused into one
# FMA, so both builds compute every result to the same bits (the engine's SIMD
# paths: test EventTree.ReplaceThreeIsSetAndRefresh; whole runs compared in
# docs/performance.md).
#
# Eigen sums in packets of the vector width, so its fits (shockgas/compare/statistics.cpp)
# would change in the last bits with AVX: that file keeps the portable x86-64
# target (it is the only one that includes Eigen), and SHOCKGAS_NATIVE defaults
# to ON only on x86-64, where that target is known.
include(CheckCXXCompilerFlag)
check_cxx_compiler_flag(-march=native SHOCKGAS_COMPILER_HAS_MARCH_NATIVE)
set(_native_default OFF)
if(SHOCKGAS_COMPILER_HAS_MARCH_NATIVE AND CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64)$")
  set(_native_default ON)
endif()
option(SHOCKGAS_NATIVE "Compile for the build machine's processor (-march=native); OFF: portable"
       ${_native_default})
# The options that put a file back on the portable target (shockgas/compare/CMakeLists.txt).
set(SHOCKGAS_PORTABLE_OPTIONS "")
set(SHOCKGAS_BUILD_INSTRUCTION_SETS "")

check_cxx_compiler_flag(-ffp-contract=off SHOCKGAS_COMPILER_HAS_FP_CONTRACT)
if(SHOCKGAS_COMPILER_HAS_FP_CONTRACT)
  add_compile_options(-ffp-contract=off)
endif()

if(SHOCKGAS_NATIVE)
  add_compile_options(-march=native)
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64)$")
    set(SHOCKGAS_PORTABLE_OPTIONS -march=x86-64 -mtune=generic)
  endif()
  # The processor GCC resolved -march=native to, for the record (version.hpp).
  set(_march "")
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -march=native -Q --help=target
                  OUTPUT_VARIABLE _target ERROR_QUIET RESULT_VARIABLE _rc)
  if(_rc EQUAL 0 AND _target MATCHES "-march=[ \t]*([^ \t\n]+)")
    set(_march " = ${CMAKE_MATCH_1}")
  endif()
  set(SHOCKGAS_BUILD_TARGET "native (-march=native${_march})")
  # The instruction sets -march=native enables, of those the start-up check can ask
  # the processor about (the SHOCKGAS_INSTRUCTION_SET lines of instruction_sets.cpp).
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -march=native -dM -E -x c++ /dev/null
                  OUTPUT_VARIABLE _macros ERROR_QUIET RESULT_VARIABLE _rc)
  file(STRINGS ${PROJECT_SOURCE_DIR}/shockgas/core/instruction_sets.cpp _lines
       REGEX "SHOCKGAS_INSTRUCTION_SET\\(\"")
  string(REGEX MATCHALL "SHOCKGAS_INSTRUCTION_SET\\(\"[a-z0-9.]+\"" _probes "${_lines}")
  foreach(_probe ${_probes})
    string(REGEX REPLACE ".*\"([a-z0-9.]+)\"" "\\1" _isa "${_probe}")
    string(TOUPPER "${_isa}" _macro)
    string(REPLACE "." "_" _macro "${_macro}")
    if(_rc EQUAL 0 AND _macros MATCHES "#define __${_macro}__ 1")
      string(APPEND SHOCKGAS_BUILD_INSTRUCTION_SETS " ${_isa}")
    endif()
  endforeach()
  string(STRIP "${SHOCKGAS_BUILD_INSTRUCTION_SETS}" SHOCKGAS_BUILD_INSTRUCTION_SETS)
else()
  set(SHOCKGAS_BUILD_TARGET "portable (the compiler's default target)")
endif()
message(STATUS "shockgas instruction set: ${SHOCKGAS_BUILD_TARGET}; SHOCKGAS_NATIVE=OFF for a portable build")
