#include "shockgas/app/cli/upgrade.hpp"

#include <filesystem>
#include <sstream>

#include "shockgas/app/cli/info.hpp"
#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/files/file_problem.hpp"
#include "shockgas/app/output/layout_version.hpp"
#include "shockgas/app/output/result_reader.hpp"

namespace shockgas::app {

std::string upgrade_answer(const std::string& path) {
  const std::filesystem::path file = result_file_of(path);
  const ResultContents contents = read_every_chunk(file, check_result_file(file));
  const RunFilesCheck files = check_run_files(path);
  if (!files.differences.empty())
    throw result_problem(files.directory, "not as its manifest.json records", files.differences);
  // No attribute: layout 1.0 (an empty one was refused when the file was read).
  const std::string stated = contents.attribute("/", "layout_version");
  const std::string layout = layout_version_text(
      parse_layout_version(file.string(), stated.empty() ? std::nullopt : std::optional(stated)));
  std::ostringstream out;
  out << file.string() << ": layout " << layout << ", which this shockgas reads as it is (layouts 1.0 to "
      << kLayoutVersion.major << ".x): nothing to upgrade.\n";
  if (layout != layout_version_text())
    out << "It is not rewritten in layout " << layout_version_text()
        << ": the new file would carry checksums taken now, vouching for bytes nobody can check any "
           "more. To have its results in layout "
        << layout_version_text()
        << ", run its scene again (its /@scene_text; the seed gives the same realizations): "
           "docs/output.md, \"Layout version\".\n";
  return out.str();
}

}  // namespace shockgas::app
