#pragma once
// What a message to the user must never hold: the text of a library beneath
// shockgas (the C++ standard library's "vector::_M_default_append" or
// "map::at", nlohmann's "[json.exception...]", toml++'s types, an uncaught
// exception's "terminate called"), found by a hostile pass (issue 34, finding
// 11). Shared by the tests of damaged files and of hostile values.
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace shockgas::app::testing {

inline const std::vector<std::string> kLibraryTexts = {
    "_M_", "::at", "json.exception", "toml::", "basic_string", "std::", "terminate called"};

// Fails the test once for each library text in `said`; `what` says whose message it was.
inline void expect_no_library_text(const std::string& said, const std::string& what) {
  for (const std::string& leak : kLibraryTexts)
    EXPECT_EQ(said.find(leak), std::string::npos) << what << ": " << said;
}

}  // namespace shockgas::app::testing
