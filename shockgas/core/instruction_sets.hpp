#pragma once
// The processor a build needs, checked before any of its code runs.
//
// A build with SHOCKGAS_NATIVE=ON (cmake/Native.cmake) is compiled for the
// build machine's processor: on one without those instructions (AVX-512 on an
// older x86-64, say) it would die of SIGILL at the first one, without a word.
// instruction_sets.cpp is compiled for the portable target (core/CMakeLists.txt),
// and a constructor of the highest priority compares the instruction sets the
// compiler was allowed to use (kBuildInstructionSets, version.hpp) with what the
// processor reports (CPUID, __builtin_cpu_supports): a lack is a message on
// stderr and exit status 1, before any static initialiser of the program or the
// Python module runs. Its path uses C functions only, so that no inline
// function compiled for the native target can be linked into it.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace shockgas {

// The instruction sets this build can ask the processor about, by GCC's names
// ("avx2", "avx512f", ...): cmake/Native.cmake reads the list from
// instruction_sets.cpp and records those a native build's compiler enables.
std::vector<std::string> checkable_instruction_sets();

// Whether this processor has the instruction set `name` (an unknown name: false).
bool processor_has(std::string_view name);

// The message for a processor judged by `has`, for a build that needs the
// instruction sets `needed` (names separated by spaces) and was compiled for
// `build_target`: the ones it lacks, in order, and what to do; "" when none.
std::string instruction_set_message(std::string_view needed, std::string_view build_target,
                                    const std::function<bool(std::string_view)>& has);

}  // namespace shockgas
