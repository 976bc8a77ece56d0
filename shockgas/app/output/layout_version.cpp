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

}  // namespace shockgas::app
