// The start-up check of the processor against the build's instruction sets
// (shockgas/core/instruction_sets.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "shockgas/core/instruction_sets.hpp"
#include "shockgas/version.hpp"

namespace shockgas {
namespace {

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

TEST(InstructionSets, TheBuildNeedsOnlyWhatTheCheckCanAskAndThisProcessorHas) {
  const std::vector<std::string> known = checkable_instruction_sets();
#if defined(__x86_64__)
  EXPECT_NE(std::find(known.begin(), known.end(), "avx2"), known.end());
  EXPECT_NE(std::find(known.begin(), known.end(), "avx512f"), known.end());
#endif
  for (const std::string& isa : words(kBuildInstructionSets)) {
    EXPECT_NE(std::find(known.begin(), known.end(), isa), known.end()) << isa;
    EXPECT_TRUE(processor_has(isa)) << isa << ": this test runs where the build's check passed";
  }
  EXPECT_FALSE(processor_has("avx9000"));
  EXPECT_EQ(instruction_set_message(kBuildInstructionSets, kBuildTarget, processor_has), "");
#if defined(__AVX2__)
  // a native build on a processor with AVX2 records it
  EXPECT_NE(std::string(kBuildInstructionSets).find("avx2"), std::string::npos);
#endif
}

TEST(InstructionSets, AProcessorWithoutThemGetsTheirNamesAndWhatToDo) {
  // an older processor: AVX2 without AVX-512
  const auto older = [](std::string_view isa) { return isa.substr(0, 6) != "avx512"; };
  const std::string message =
      instruction_set_message("  avx avx2 avx512f  bmi2 avx512bw", "native (-march=native = znver4)", older);
  EXPECT_EQ(
      message,
      "shockgas: this build was compiled for native (-march=native = znver4) and uses instructions this "
      "processor lacks: avx512f, avx512bw. Build it on this machine, or build a portable binary or "
      "package with cmake -DSHOCKGAS_NATIVE=OFF (docs/install.md).\n");
  EXPECT_EQ(instruction_set_message("avx avx2", "native", older), "");
  EXPECT_EQ(instruction_set_message("", "portable", [](std::string_view) { return false; }), "");
}

}  // namespace
}  // namespace shockgas
