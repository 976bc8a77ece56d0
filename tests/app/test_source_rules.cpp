// Rules of the repository that a reader relies on: each solver's and restitution
// law's name is written in one source only (its registration, or its declaration),
// sources cite only documents of the repository, includes run one way down the
// layers, no source file outgrows what can be read at once, and README's
// commands are the ones the continuous integration runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "shockgas/continuum/registry.hpp"
#include "shockgas/particles/params.hpp"
#include "shockgas/particles/restitution_laws.hpp"

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
  // "auto" names no solver but the choice of one, the word every key uses for its
  // automatic choice (particles.schedule, continuum.hopf_cole_path): not counted.
  for (const auto& n : enum_choices<particles::ParticleSolver>())
    if (n != name_of(particles::ParticleSolver::automatic)) names.push_back(n);
  for (const auto& n : particles::restitution_law_names()) names.push_back(n);
  for (const auto& n : names) where[n];
  for (const auto& path : files(kSourceFolders, {".cpp", ".hpp", ".h"}))
    for (const auto& literal : string_literals(read_file(path)))
      if (where.count(literal)) where[literal].insert(fs::relative(path, kRoot).string());
  EXPECT_EQ(names.size(), 10u);  // 7 continuum solvers, 2 particle solvers, 1 restitution law
  for (const auto& [name, in] : where) {
    std::string list;
    for (const auto& f : in) list += " " + f;
    EXPECT_EQ(in.size(), 1u) << "\"" << name << "\" is written in:" << list;
  }
}

TEST(SourceRules, SourcesCiteOnlyDocumentsOfTheRepository) {
  std::vector<std::string> folders = kSourceFolders;
  for (const char* f : {"tests", "plots", "scripts", "data", "docs", "examples", "lab"}) folders.push_back(f);
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

// The layers of docs/design.md, as scripts/dev/draw_layers.py draws them: a module
// includes only modules of a lower rank (particles and continuum share one, so
// neither includes the other), app's rooms only rooms before them in kRooms, and
// nothing includes the facade shockgas/shockgas.hpp, which may include anything.
const std::map<std::string, int> kModules = {{"core", 0},    {"particles", 1}, {"continuum", 1},
                                             {"compare", 2}, {"studies", 3},   {"app", 4}};
const std::vector<std::string> kRooms = {"files",  "scene", "records",  "directory", "output", "input",
                                         "report", "run",   "ensemble", "jobs",      "cli"};

// "core", "app/run", "shockgas.hpp" (the facade), or "" (a file of no folder: the
// generated shockgas/version.hpp), for a path below shockgas/.
std::string layer_of(const std::string& path) {
  const auto slash = path.find('/');
  if (slash == std::string::npos) return path == "shockgas.hpp" ? path : "";
  std::string module = path.substr(0, slash);
  const auto second = path.find('/', slash + 1);
  if (module != "app" || second == std::string::npos) return module;
  return path.substr(0, second);
}

// Why an include from one layer into another runs against the order, or "" when it does not.
std::string against_the_order(const std::string& from, const std::string& to) {
  if (to == "shockgas.hpp") return "the facade is included by no part of shockgas";
  if (from == "shockgas.hpp" || to.empty() || from == to) return "";
  const std::string m_from = from.substr(0, from.find('/')), m_to = to.substr(0, to.find('/'));
  for (const auto& m : {m_from, m_to})
    if (!kModules.count(m)) return m + " is in no layer: add it to the order (docs/design.md)";
  if (m_from != m_to) return kModules.at(m_to) < kModules.at(m_from) ? "" : m_to + " is not below " + m_from;
  const auto room = [](const std::string& layer) {
    return std::find(kRooms.begin(), kRooms.end(), layer.substr(layer.find('/') + 1)) - kRooms.begin();
  };
  for (const auto& l : {from, to})
    if (room(l) == static_cast<std::ptrdiff_t>(kRooms.size()))
      return l + " is no room of app: add it to the order";
  return room(to) < room(from) ? "" : to + " comes after " + from + " in the rooms' order";
}

TEST(SourceRules, IncludesRunDownTheLayers) {
  EXPECT_EQ(against_the_order("particles", "continuum"), "continuum is not below particles");
  EXPECT_EQ(against_the_order("app/run", "app/report"), "");
  EXPECT_NE(against_the_order("app/files", "app/cli"), "");
  const std::regex include(R"re(^\s*#\s*include\s*["<]shockgas/([^">]+)[">])re");
  int includes = 0;
  for (const auto& path : files({"shockgas"}, {".cpp", ".hpp", ".h"})) {
    const std::string from = layer_of(fs::relative(path, kRoot / "shockgas").generic_string());
    std::istringstream text(read_file(path));
    int line_number = 0;
    for (std::string line; std::getline(text, line);) {
      ++line_number;
      std::smatch m;
      if (!std::regex_search(line, m, include)) continue;
      ++includes;
      const std::string why = against_the_order(from, layer_of(m[1].str()));
      EXPECT_EQ(why, "") << fs::relative(path, kRoot).string() << ":" << line_number << " includes shockgas/"
                         << m[1].str() << ": " << why;
    }
  }
  EXPECT_GT(includes, 400);  // the includes were found at all
}

// The HDF5 library may crash inside a damaged file: every reader of a result
// file goes through result_reader.hpp, which runs the library in a child
// process (finding: `animate`, `merge` and the Python module's load opened
// the file themselves, and segfaulted).
TEST(SourceRules, EveryResultFileIsReadThroughTheResultReader) {
  for (const auto& path : files(kSourceFolders, {".cpp", ".hpp"})) {
    const std::string name = path.filename().string();
    if (name == "result_reader.cpp" || name == "hdf5_file.cpp" || name == "hdf5_file.hpp") continue;
    EXPECT_EQ(read_file(path).find("Hdf5File::open("), std::string::npos)
        << path << " opens a result file itself: read it with read_result (result_reader.hpp)";
  }
}

// House style: one concept per file, about 400 lines at most; the lab's page too.
TEST(SourceRules, NoSourceFileIsLongerThanAboutFourHundredLines) {
  std::vector<std::string> folders = kSourceFolders;
  for (const char* f : {"tests", "plots", "scripts", "examples", "lab"}) folders.push_back(f);
  for (const auto& path : files(folders, {".cpp", ".hpp", ".h", ".py", ".js", ".html", ".css"})) {
    const std::string text = read_file(path);
    const auto lines = std::count(text.begin(), text.end(), '\n');
    EXPECT_LE(lines, 420) << path;
  }
}

// README's two commands are the ones that run: the quickstart script exists and
// the continuous integration runs README's test command (the block after it) verbatim.
TEST(SourceRules, TheContinuousIntegrationRunsTheReadmeTestCommandVerbatim) {
  const std::string readme = read_file(kRoot / "README.md");
  const std::string fence = "```sh\n";
  const auto first = readme.find(fence + "scripts/quickstart\n```");
  ASSERT_NE(first, std::string::npos) << "README's first command is scripts/quickstart";
  EXPECT_TRUE(fs::exists(kRoot / "scripts" / "quickstart"));
  const auto second = readme.find(fence, first + fence.size());
  ASSERT_NE(second, std::string::npos);
  const auto begin = second + fence.size();
  const std::string command = readme.substr(begin, readme.find('\n', begin) - begin);
  const std::string ci = read_file(kRoot / ".ci" / "run");
  EXPECT_NE(ci.find("\n" + command + "\n"), std::string::npos) << command;
}

}  // namespace
}  // namespace shockgas::app
