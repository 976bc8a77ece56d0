#pragma once
// The version header of a build that needs an instruction set no processor has
// (test InstructionSets.AProgramOnAProcessorWithoutThemStopsBeforeItsCode).
namespace shockgas {
inline constexpr const char* kBuildTarget = "a processor to come";
inline constexpr const char* kBuildInstructionSets = "sse3 avx9000";
}  // namespace shockgas
