#pragma once
// The pieces of a self-contained HTML page (report.html): escaped text, files
// embedded as data: URIs, the titles the plotting scripts write into their
// PNGs, and the page around a body, with its own style and a content policy
// that lets the page load nothing but what it carries.
#include <filesystem>
#include <optional>
#include <string>

namespace shockgas::app::html {

// text with &, <, >, " escaped.
std::string escape(const std::string& text);

// "data:<mime>;base64,..." holding the file's bytes.
std::string data_uri(const std::filesystem::path& file, const std::string& mime);

// The PNG's "Title" (matplotlib's savefig metadata: tEXt, or uncompressed iTXt
// when it holds more than Latin-1, as a title in plain Unicode does), if it has one.
std::optional<std::string> png_title(const std::filesystem::path& png);

// The whole page: title, inline style (large type for a projector, one column
// that narrows to a laptop or phone), body.
std::string page(const std::string& title, const std::string& body);

}  // namespace shockgas::app::html
