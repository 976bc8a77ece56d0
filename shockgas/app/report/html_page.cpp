// The pieces of a self-contained HTML page (html_page.hpp).
#include "shockgas/app/report/html_page.hpp"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <vector>

namespace shockgas::app::html {

namespace {

std::vector<unsigned char> read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t a = bytes[i], b = i + 1 < bytes.size() ? bytes[i + 1] : 0,
                        c = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const std::uint32_t triple = (a << 16) | (b << 8) | c;
    out += kAlphabet[(triple >> 18) & 63];
    out += kAlphabet[(triple >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(triple >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[triple & 63] : '=';
  }
  return out;
}

std::uint32_t big_endian(const std::vector<unsigned char>& b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) | (std::uint32_t{b[at + 2]} << 8) |
         b[at + 3];
}

// Large type and generous spacing for a projector; the column narrows with the
// screen. System fonts only: the page fetches nothing.
constexpr const char* kStyle = R"(
:root { color-scheme: light; --ink: #16181d; --muted: #4a5060; --rule: #d5d9e0; --band: #f3f5f8; --accent: #1f5fbf; }
* { box-sizing: border-box; }
body { margin: 0; color: var(--ink); background: #fff; line-height: 1.5;
       font: clamp(16px, 0.55vw + 12px, 22px) system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif; }
main { max-width: 76rem; margin: 0 auto; padding: 1.5rem clamp(1rem, 3vw, 3rem) 4rem; }
h1 { font-size: 2.1em; margin: 0.4em 0 0.2em; }
h2 { font-size: 1.45em; margin: 2em 0 0.6em; border-bottom: 2px solid var(--rule); padding-bottom: 0.2em; }
h3 { font-size: 1.1em; margin: 1.4em 0 0.4em; color: var(--muted); }
p.lead { font-size: 1.15em; max-width: 60rem; }
nav a { margin-right: 1.2em; color: var(--accent); }
figure { margin: 1.2em 0 2em; }
img, video { display: block; max-width: 100%; height: auto; border: 1px solid var(--rule); }
figcaption { color: var(--muted); margin-top: 0.4em; }
table { border-collapse: collapse; width: 100%; margin: 0.5em 0 1em; font-size: 0.92em; }
table.figures { table-layout: fixed; }
table.figures col.meaning { width: 38%; } table.figures col.value { width: 17%; }
table.figures col.theory { width: 22%; } table.figures col.key { width: 23%; }
td.key code { overflow-wrap: anywhere; }
th, td { text-align: left; vertical-align: top; padding: 0.45em 0.7em; border-bottom: 1px solid var(--rule); }
th { background: var(--band); }
td.value, td.theory { font-variant-numeric: tabular-nums; overflow-wrap: anywhere; }
td.key code { font-size: 0.95em; }
tr:nth-child(even) td { background: #fafbfc; }
pre { background: var(--band); padding: 1em; overflow-x: auto; font-size: 0.85em; white-space: pre-wrap; }
details summary { cursor: pointer; color: var(--accent); margin: 0.6em 0; }
.muted { color: var(--muted); }
p.warning { border-left: 4px solid #b3261e; padding: 0.3em 0.8em; background: #fbeaea; }
@media (max-width: 700px) { table.figures { table-layout: auto; } table { font-size: 0.85em; } }
)";

}  // namespace

std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string data_uri(const std::filesystem::path& file, const std::string& mime) {
  return "data:" + mime + ";base64," + base64(read_bytes(file));
}

std::optional<std::string> png_title(const std::filesystem::path& png) {
  const auto b = read_bytes(png);
  for (std::size_t at = 8; at + 12 <= b.size();) {  // chunks after the 8-byte signature
    const std::uint32_t length = big_endian(b, at);
    if (at + 12 + length > b.size()) break;
    const std::string type(b.begin() + static_cast<std::ptrdiff_t>(at + 4),
                           b.begin() + static_cast<std::ptrdiff_t>(at + 8));
    if (type == "IDAT" || type == "IEND") break;  // matplotlib writes its text before the image data
    const auto first = b.begin() + static_cast<std::ptrdiff_t>(at + 8);
    const std::string data(first, first + length);
    const auto nul = data.find('\0');
    const bool title = nul != std::string::npos && data.substr(0, nul) == "Title";
    if (title && type == "tEXt") return data.substr(nul + 1);
    // iTXt (matplotlib's for text beyond Latin-1): keyword 0 compressed method language 0 translated 0 UTF-8
    if (title && type == "iTXt" && nul + 3 < data.size() && data[nul + 1] == 0) {
      const auto language_end = data.find('\0', nul + 3);
      const auto translated_end =
          language_end == std::string::npos ? language_end : data.find('\0', language_end + 1);
      if (translated_end != std::string::npos) return data.substr(translated_end + 1);
    }
    at += 12 + length;
  }
  return std::nullopt;
}

std::string page(const std::string& title, const std::string& body) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         // nothing but what the page carries: images and video as data: URIs, its own style
         "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; "
         "media-src data:; style-src 'unsafe-inline'\">\n"
         "<title>" +
         escape(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<main>\n" + body +
         "</main>\n</body>\n</html>\n";
}

}  // namespace shockgas::app::html
