#include "shockgas/app/output/layout_version.hpp"

#include <charconv>

#include "shockgas/app/directory/result_check.hpp"

namespace shockgas::app {

namespace {

// A whole number without sign at the front of `text`, advancing it; -1 if none.
int leading_number(std::string_view& text) {
  int value = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || value < 0) return -1;
  text.remove_prefix(static_cast<std::size_t>(end - text.data()));
  return value;
}

}  // namespace

std::string layout_version_text(LayoutVersion v) {
  return std::to_string(v.major) + "." + std::to_string(v.minor);
}

LayoutVersion parse_layout_version(const std::string& file, const std::optional<std::string>& stated) {
  if (!stated) return {1, 0};
  const std::string& text = *stated;
  std::string_view rest = text;
  const int major = leading_number(rest);
  const bool dot = !rest.empty() && rest.front() == '.';
  if (dot) rest.remove_prefix(1);
  const int minor = dot ? leading_number(rest) : -1;
  if (major < 1 || minor < 0 || !rest.empty())
    throw result_problem(file, "damaged", "its layout_version \"" + text + "\" is not major.minor");
  return {major, minor};
}

void check_layout_version(const std::string& file, const std::optional<std::string>& text) {
  const LayoutVersion v = parse_layout_version(file, text);
  if (v.major > kLayoutVersion.major)
    throw result_problem(file, "of a newer layout",
                         "written in layout " + layout_version_text(v) +
                             " by a newer shockgas; this one reads "
                             "layouts 1.0 to " +
                             std::to_string(kLayoutVersion.major) +
                             ".x (docs/output.md, "
                             "\"Layout version\")");
}

namespace {

bool at_least(LayoutVersion v, LayoutVersion since) {
  return v.major != since.major ? v.major > since.major : v.minor >= since.minor;
}

}  // namespace

void check_layout_marks(const std::string& file, LayoutVersion v, const LayoutMarks& marks) {
  if (!marks.shockgas_version)
    throw result_problem(file, "not a result file",
                         "an HDF5 file without /@shockgas_version, which every result file carries: "
                         "not written by shockgas");
  const std::string layout = "layout " + layout_version_text(v) + " (its /@layout_version)";
  if (at_least(v, kOwnChecksumSince) && !marks.own_checksum)
    throw result_problem(
        file, "damaged",
        "its first 512 bytes hold no checksum of the file, which every file of " + layout +
            " carries: it was rewritten by another program, or its checksum block was damaged");
  if (at_least(v, kAttributesDigestSince) && !marks.attributes_digest)
    throw result_problem(file, "damaged",
                         "it has no /@attributes_sha256, which every file of " + layout +
                             " carries: it was rewritten by another program, or the attribute was removed");
}

}  // namespace shockgas::app
