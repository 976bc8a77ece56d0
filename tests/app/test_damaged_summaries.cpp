// A damaged summary.json whose manifest was written for it (finding 11 of a
// hostile pass: library text such as "[json.exception.parse_error.101]",
// "map::at" or "vector::_M_default_append" reached the user). Its readers are
// report.html's writer (run, merge, animate) and the outputs a Python `load`
// returns: whatever the damage, each gives its result or one of shockgas's own
// errors, whose message holds no text of the C++ or JSON library; `info`
// exits 0 or 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "child_run.hpp"
#include "library_texts.hpp"
#include "run_dir_checks.hpp"
#include "scene_a_run.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/report/report_html.hpp"
#include "shockgas/app/run/captured_outputs.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

// One run's directory, made once for the tests below (each copies it).
const fs::path& pristine() {
  static const fs::path dir = scene_a_run("damaged-summaries");
  return dir;
}

// The damages: structural ones, and seeded flips of three bytes.
std::vector<std::pair<std::string, std::string>> damaged_texts(const std::string& sound) {
  std::vector<std::pair<std::string, std::string>> out = {
      {"cut in half", sound.substr(0, sound.size() / 2)},
      {"not JSON", "xx"},
      {"empty", ""},
      {"an array", "[]"},
      {"a number", "3"},
      {"no keys", "{}"},
      {"a NUL in the scene's name", std::string("{\"scene\": \"a") + '\0' + "b\"}"},
  };
  std::mt19937 rng(11);
  for (int k = 0; k < 4; ++k) {
    std::string text = sound;
    for (int i = 0; i < 3; ++i) text[rng() % text.size()] = static_cast<char>(rng() % 256);
    out.emplace_back("3 bytes flipped, seed " + std::to_string(k), text);
  }
  return out;
}

// What `read` says: "" when it returns, else its error's message; an error
// that is not one of shockgas's own fails the test.
template <typename Read>
std::string message_of(Read read, const std::string& what) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  } catch (const RunError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": not an error of shockgas's own: " << e.what();
    return e.what();
  }
  return "";
}

TEST(DamagedSummaries, EveryMessageIsShockgassOwn) {
  const std::string sound = read_text(pristine() / "summary.json");
  int k = 0;
  for (const auto& [what, text] : damaged_texts(sound)) {
    const fs::path run = fresh_dir("damaged-summary-" + std::to_string(k++)) / "run";
    fs::copy(pristine(), run, fs::copy_options::recursive);
    write_text(run / "summary.json", text);
    write_manifest(run, "alpha");  // as if the damage were meant: the readers see it
    expect_no_library_text(message_of([&] { write_report_html(run); }, what + ", report.html"), what);
    expect_no_library_text(message_of([&] { read_outputs(run.string()); }, what + ", load"), what);
    const auto [code, err] = run_child({"info", run.string()});
    EXPECT_TRUE(code == 0 || code == 2) << what << ": exit " << code << "\n" << err;
    expect_no_library_text(err, what + ", info");
  }
}

}  // namespace
}  // namespace shockgas::app
