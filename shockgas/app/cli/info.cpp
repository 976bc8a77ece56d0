#include "shockgas/app/cli/info.hpp"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstring>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>

#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/output/output_layout.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

std::string shape_text(const std::vector<std::uint64_t>& shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
  return s + (shape.size() == 1 ? ",)" : ")");
}

std::string intact_text(Verification v) {
  switch (v) {
    case Verification::manifest:
      return "  (intact: size and SHA-256 as its manifest.json records)";
    case Verification::own_checksum:
      return "  (intact: size and SHA-256 as its first 512 bytes record)";
    case Verification::no_manifest:
      break;
  }
  return "";
}

std::string describe(const Hdf5File& file, const std::string& path) {
  std::ostringstream out;
  out << path << intact_text(file.verification()) << "\n\nprovenance:\n";
  std::string scene_text, resolved;
  for (const auto& [name, value] : file.attributes("/")) {
    if (name == "scene_text")
      scene_text = value;
    else if (name == "resolved_parameters")
      resolved = value;
    else
      out << "  " << name << ": " << value << "\n";
  }
  out << "\ndatasets (docs/output.md explains each):\n";
  for (const auto& d : file.datasets()) {
    out << "  " << d.path << "  " << d.type << " " << shape_text(d.shape);
    if (!d.unit.empty()) out << "  [" << d.unit << "]";
    if (!d.description.empty()) out << "  " << d.description;
    if (!find_in_layout(LayoutEntry::Kind::dataset, d.path)) out << "  (not in this version's layout)";
    out << "\n";
  }
  out << "\nscene (as given):\n" << scene_text << "\n";
  while (!resolved.empty() && resolved.back() == '\n') resolved.pop_back();
  if (!resolved.empty()) out << "resolved parameters:\n" << resolved << "\n";
  return out.str();
}

// The child's answer on the pipe: 'O' text, or 'E' problem '\0' detail.
void answer(int fd, const std::string& message) {
  for (std::size_t done = 0; done < message.size();) {
    const ssize_t n = write(fd, message.data() + done, message.size() - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
}

// The child's whole answer, or what it gave before it died or kTimeout passed.
std::string collect(int fd) {
  constexpr auto kTimeout = std::chrono::seconds(120);
  const auto deadline = std::chrono::steady_clock::now() + kTimeout;
  std::string text;
  char block[65536];
  for (pollfd p{fd, POLLIN, 0}; std::chrono::steady_clock::now() < deadline;) {
    if (poll(&p, 1, 100) <= 0) continue;
    const ssize_t n = read(fd, block, sizeof block);
    if (n <= 0) break;
    text.append(block, static_cast<std::size_t>(n));
  }
  return text;
}

// The answer of job(), run in a child process on a file that may be damaged:
// the HDF5 library may crash inside it, and then only the child dies. Its
// failures come back as a FileProblem of the file.
std::string isolated(const fs::path& file, const std::function<std::string()>& job) {
  int fds[2];
  if (pipe(fds) != 0) throw RunError(std::string("pipe: ") + std::strerror(errno));
  const pid_t child = fork();
  if (child == 0) {
    close(fds[0]);
    try {
      answer(fds[1], "O" + job());
    } catch (const FileProblem& e) {
      answer(fds[1], "E" + e.problem() + '\0' + e.detail());
    } catch (const std::exception& e) {
      answer(fds[1], std::string("E") + "unreadable" + '\0' + e.what());
    }
    _exit(0);
  }
  close(fds[1]);
  const std::string text = child > 0 ? collect(fds[0]) : "";
  close(fds[0]);
  int status = 0;
  if (child > 0) {
    kill(child, SIGKILL);  // no-op once it has exited
    waitpid(child, &status, 0);
  }
  const bool finished = child > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0 && !text.empty();
  if (finished && text[0] == 'O') return text.substr(1);
  if (finished && text[0] == 'E') {
    const auto zero = text.find('\0');
    throw result_problem(file.string(), text.substr(1, zero - 1), text.substr(zero + 1));
  }
  throw result_problem(file.string(), "damaged",
                       "the HDF5 library failed inside it (" +
                           std::string(WIFSIGNALED(status) ? strsignal(WTERMSIG(status)) : "no answer") +
                           "), and it has no manifest.json to check it against");
}

std::string describe_isolated(const fs::path& file) {
  return isolated(file, [&] {
    const Hdf5File h5 = Hdf5File::open(file.string(), Verification::no_manifest);
    h5.check_every_chunk();
    return describe(h5, file.string());
  });
}

// Where the damage of a file that failed its checksum lies, read in a child
// process: the datasets whose chunks fail their Fletcher32 checksums, or the
// library's reason where it cannot read the file's structure.
std::string damaged_parts(const fs::path& file) {
  try {
    return isolated(file, [&] {
      std::string names;
      for (const UnreadableDataset& d :
           Hdf5File::open(file.string(), Verification::no_manifest).unreadable_datasets())
        names += (names.empty() ? "" : ", ") + d.path + " (" + d.reason + ")";
      return names.empty() ? "every dataset reads back whole: the damage lies in its metadata, attributes or "
                             "unused bytes"
                           : "dataset " + names;
    });
  } catch (const FileProblem& e) {
    return "its HDF5 structure: " + e.detail();
  }
}

// check_result_file(file), a damage named where it lies (damaged_parts).
Verification checked_naming_damage(const fs::path& file) {
  try {
    return check_result_file(file);
  } catch (const FileProblem& e) {
    if (e.problem() != "damaged") throw;
    throw result_problem(file.string(), "damaged", e.detail() + "; " + damaged_parts(file));
  }
}

}  // namespace

std::string describe_result(const std::string& path) {
  // An output directory without a result file by its own manifest (`shockgas
  // bench`): nothing to describe but its files.
  std::error_code ec;
  if (fs::is_directory(path, ec) && !fs::exists(fs::path(path) / "result.h5", ec))
    if (const auto manifest = read_manifest(path); manifest && !manifest->find("result.h5"))
      return path + ": the output of \"" + manifest->scene + "\", which has no result file\n";
  const fs::path file = result_file_of(path);
  const Verification checked = checked_naming_damage(file);
  if (checked != Verification::no_manifest) {
    // Its bytes are as written; every chunk is still read, its Fletcher32 checked
    // (a chunk damaged before its file's checksum was taken).
    const Hdf5File h5 = Hdf5File::open(file.string(), checked);
    h5.check_every_chunk();
    return describe(h5, file.string());
  }
  std::cerr << "shockgas: warning: " << unverified_warning(file) << "\n";
  return describe_isolated(file);
}

RunFilesCheck check_run_files(const std::string& path, bool result_checked) {
  std::error_code ec;
  const fs::path file = fs::is_directory(path, ec) ? fs::path(path) / "result.h5" : fs::path(path);
  const fs::path dir = file.parent_path().empty() ? "." : file.parent_path();
  // `info result.h5`, `info .` or `info ..` name the directory by its path, not as "." or ".."
  const std::string last = dir.filename().string();
  fs::path shown =
      last.empty() || last == "." || last == ".." ? fs::absolute(dir, ec).lexically_normal() : dir;
  if (!shown.has_filename() && shown != shown.root_path()) shown = shown.parent_path();
  const auto manifest = read_manifest(dir);
  if (!manifest) return {};
  // The result file itself was checked before it was described, if listed.
  const fs::path checked =
      result_checked && manifest->find(file.filename().string()) ? file.filename() : fs::path();
  const std::vector<FileState> states = check_listed_files(dir, *manifest, checked);
  std::size_t intact = 0, wrong = 0;
  std::ostringstream listing;
  for (const FileState& f : states) {
    intact += f.intact();
    if (f.intact()) continue;
    listing << "  " << f.path << ": " << f.problem << (f.detail.empty() ? "" : " (" + f.detail + ")") << "\n";
    wrong += f.problem != "not listed";
  }
  std::string differences = differences_of(states);
  const std::size_t listed = manifest->files.size();
  std::ostringstream head;
  head << "\nfiles of " << shown.string() << " (as " << kManifestFile << " lists them, scene \""
       << manifest->scene << "\"): ";
  if (wrong == 0)
    head << "all " << listed << " intact (size and SHA-256 as recorded)\n";
  else
    head << intact << " of " << listed << " intact\n";
  if (wrong)
    differences += " (" + std::to_string(wrong) + " of the " + std::to_string(listed) + " files " +
                   kManifestFile + " lists)";
  return {head.str() + listing.str(), differences, shown.string()};
}

void print_info(const std::string& path, std::ostream& out) {
  std::optional<FileProblem> undescribed;
  try {
    out << describe_result(path);
  } catch (const FileProblem& e) {
    undescribed = e;
  }
  const RunFilesCheck files = check_run_files(path, !undescribed);
  out << files.listing << std::flush;
  if (undescribed) throw *undescribed;
  if (!files.differences.empty())
    throw result_problem(files.directory, "not as its manifest.json records", files.differences);
}

std::string describe_layout() { return output_layout_markdown(); }

}  // namespace shockgas::app
