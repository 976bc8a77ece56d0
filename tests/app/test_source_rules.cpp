// Rules of the repository that a reader relies on: each solver's name is written
// in one source only (its registration), sources cite only documents of the
// repository, and no source file outgrows what can be read at once.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "shockgas/continuum/registry.hpp"
#include "shockgas/particles/params.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;

const fs::path kRoot = SHOCKGAS_SOURCE_DIR;

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Files under the given folders of the repository with one of the extensions.
std::vector<fs::path> files(const std::vector<std::string>& folders,
                            const std::set<std::string>& extensions) {
  std::vector<fs::path> out;
  for (const auto& folder : folders)
    for (const auto& entry : fs::recursive_directory_iterator(kRoot / folder))
      if (entry.is_regular_file() && extensions.count(entry.path().extension().string()))
        out.push_back(entry.path());
  return out;
}

// The string literals of C++ text, comments skipped.
std::vector<std::string> string_literals(const std::string& code) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (code.compare(i, 2, "//") == 0) {
      i = code.find('\n', i);
      if (i == std::string::npos) break;
    } else if (code.compare(i, 2, "/*") == 0) {
      i = code.find("*/", i + 2);
      if (i == std::string::npos) break;
      ++i;
    } else if (code[i] == '\'') {
      for (++i; i < code.size() && code[i] != '\''; ++i)
        if (code[i] == '\\') ++i;
    } else if (code[i] == '"') {
      std::string literal;
      for (++i; i < code.size() && code[i] != '"'; ++i) {
        if (code[i] == '\\') literal += code[i++];
        literal += code[i];
      }
      out.push_back(literal);
    }
  }
  return out;
}

// The C++ sources of shockgas that are not tests.
const std::vector<std::string> kSourceFolders = {"shockgas", "bench", "python"};

TEST(SourceRules, EachSolverNameIsWrittenInOneSourceOnly) {
  std::map<std::string, std::set<std::string>> where;
  std::vector<std::string> names = continuum::solver_names();
  for (const auto& n : enum_choices<particles::ParticleSolver>()) names.push_back(n);
  for (const auto& n : names) where[n];
  for (const auto& path : files(kSourceFolders, {".cpp", ".hpp", ".h"}))
    for (const auto& literal : string_literals(read_file(path)))
      if (where.count(literal)) where[literal].insert(fs::relative(path, kRoot).string());
  EXPECT_EQ(names.size(), 9u);  // 7 continuum solvers, 2 particle solvers
  for (const auto& [name, in] : where) {
    std::string list;
    for (const auto& f : in) list += " " + f;
    EXPECT_EQ(in.size(), 1u) << "\"" << name << "\" is written in:" << list;
  }
}

TEST(SourceRules, SourcesCiteOnlyDocumentsOfTheRepository) {
  std::vector<std::string> folders = kSourceFolders;
  for (const char* f : {"tests", "scripts", "data", "docs", "examples"}) folders.push_back(f);
  for (const auto& path :
       files(folders, {".cpp", ".hpp", ".h", ".py", ".toml", ".json", ".cmake", ".md", ""})) {
    if (path.filename() == "test_source_rules.cpp") continue;  // names the document it looks for
    const std::string text = read_file(path);
    EXPECT_EQ(text.find("DESIGN.md"), std::string::npos)
        << path << " cites DESIGN.md, which is not in the repository";
    for (std::size_t at = text.find("docs/"); at != std::string::npos; at = text.find("docs/", at + 1)) {
      const std::size_t end = text.find(".md", at);
      if (end == std::string::npos || end - at > 40) continue;
      const std::string doc = text.substr(at, end + 3 - at);
      if (doc.find_first_of(" \n\"'`()") != std::string::npos) continue;
      EXPECT_TRUE(fs::exists(kRoot / doc)) << path << " cites " << doc << ", which does not exist";
    }
  }
}

// House style: one concept per file, about 400 lines at most.
TEST(SourceRules, NoSourceFileIsLongerThanAboutFourHundredLines) {
  std::vector<std::string> folders = kSourceFolders;
  for (const char* f : {"tests", "scripts", "examples"}) folders.push_back(f);
  for (const auto& path : files(folders, {".cpp", ".hpp", ".h", ".py"})) {
    const std::string text = read_file(path);
    const auto lines = std::count(text.begin(), text.end(), '\n');
    EXPECT_LE(lines, 420) << path;
  }
}

}  // namespace
}  // namespace shockgas::app
