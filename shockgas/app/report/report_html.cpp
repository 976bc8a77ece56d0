// report.html (report_html.hpp): the sections of the page, each from the
// output directory's files.
#include "shockgas/app/report/report_html.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/file_problem.hpp"
#include "shockgas/app/output/output_layout.hpp"
#include "shockgas/app/output/result_reader.hpp"
#include "shockgas/app/report/html_page.hpp"
#include "shockgas/app/report/report.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

constexpr std::uintmax_t kLargestEmbeddedMovie = 64u << 20;  // bytes

std::string value_text(const Json& v) {
  if (v.is_number()) return brief(v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  if (v.is_null()) return "—";
  if (v.is_array()) {
    std::string s;
    for (const auto& item : v) s += (s.empty() ? "" : ", ") + value_text(item);
    return "[" + s + "]";
  }
  if (v.is_object()) {
    std::string s;
    for (const auto& [k, item] : v.items()) s += (s.empty() ? "" : ", ") + k + " = " + value_text(item);
    return s;
  }
  return v.dump();
}

const Json* lookup(const Json& summary, const std::string& dotted) {
  const Json* node = &summary;
  std::stringstream in(dotted);
  for (std::string part; std::getline(in, part, '.');) {
    if (!node->is_object() || !node->contains(part)) return nullptr;
    node = &(*node)[part];
  }
  return node;
}

// The theory text with each {key} replaced by that key's value in the summary.
std::string theory_text(const std::string& theory, const Json& summary) {
  std::string out;
  for (std::size_t i = 0; i < theory.size(); ++i) {
    const auto close = theory.find('}', i);
    if (theory[i] != '{' || close == std::string::npos) {
      out += theory[i];
      continue;
    }
    const std::string key = theory.substr(i + 1, close - i - 1);
    const Json* v = lookup(summary, key);
    const LayoutEntry* e = find_in_layout(LayoutEntry::Kind::summary, key);
    const bool unit = v && v->is_number() && e && !e->unit.empty() && e->unit != "1";
    out += v ? value_text(*v) + (unit ? " " + e->unit : "") : key;
    i = close;
  }
  return out;
}

bool law_holds(const std::string& law, const Json& summary) {
  const Json* holds = lookup(summary, "theory." + law + ".holds");
  return holds && holds->is_boolean() && holds->get<bool>();
}

// The theory cell of a row: what theory says of it where its law holds for
// this run (the summary's theory.<law>.holds), "no theory for this scene"
// where none of its laws does. data-laws lists the laws the cell states.
std::string theory_cell(const std::vector<Theory>& theories, const Json& summary) {
  std::string text, laws, refused;
  for (const Theory& t : theories) {
    if (!t.law.empty() && !law_holds(t.law, summary)) {
      refused += (refused.empty() ? "" : " ") + t.law;
      continue;
    }
    text += (text.empty() ? "" : "; ") + theory_text(t.value, summary);
    if (!t.law.empty()) laws += (laws.empty() ? "" : " ") + t.law;
  }
  if (text.empty() && !refused.empty())
    return "<td class=\"theory\" data-refused=\"" + refused + "\">no theory for this scene</td>";
  return "<td class=\"theory\"" + (laws.empty() ? std::string() : " data-laws=\"" + laws + "\"") + ">" +
         html::escape(text) + "</td>";
}

struct Row {
  std::string key;
  const Json* value;
  const LayoutEntry* entry;
};

// Every declared key of the summary, in its order: a declared path is a row,
// an undeclared object is opened.
void collect(const Json& node, const std::string& prefix, std::vector<Row>& rows) {
  for (const auto& [k, v] : node.items()) {
    const std::string key = prefix.empty() ? k : prefix + "." + k;
    if (const LayoutEntry* e = find_in_layout(LayoutEntry::Kind::summary, key))
      rows.push_back({key, &v, e});
    else if (v.is_object())
      collect(v, key, rows);
  }
}

std::string figures_table(const Json& summary) {
  std::vector<Row> rows;
  collect(summary, "", rows);
  std::ostringstream out;
  std::vector<Part> order;
  for (const auto& r : rows)
    if (r.entry->part != Part::provenance && r.entry->part != Part::sweep &&
        std::find(order.begin(), order.end(), r.entry->part) == order.end())
      order.push_back(r.entry->part);
  for (Part part : order) {
    out << "<h3>" << html::escape(part_title(part))
        << "</h3>\n<table class=\"figures\">\n<colgroup><col class=\"meaning\"><col class=\"value\">"
        << "<col class=\"theory\"><col class=\"key\"></colgroup>\n<thead><tr><th>meaning</th><th>value</th>"
        << "<th>theory</th><th>key</th></tr></thead>\n<tbody>\n";
    for (const auto& r : rows) {
      if (r.entry->part != part) continue;
      const std::string unit = r.entry->unit == "1" || r.entry->unit.empty() ? "" : " " + r.entry->unit;
      out << "<tr><td>" << html::escape(r.entry->description) << "</td><td class=\"value\">"
          << html::escape(value_text(*r.value) + (r.value->is_number() ? unit : "")) << "</td>"
          << theory_cell(r.entry->theory, summary) << "<td class=\"key\"><code>" << html::escape(r.key)
          << "</code></td></tr>\n";
    }
    out << "</tbody>\n</table>\n";
  }
  return out.str();
}

std::map<std::string, std::string> provenance(const ResultContents& file) {
  std::map<std::string, std::string> attrs;
  for (const auto& [name, value] : file.attributes_of("/")) attrs[name] = value;
  return attrs;
}

// The parameters the run was made with (result.h5's resolved_parameters).
toml::table resolved(const std::map<std::string, std::string>& p) {
  const auto it = p.find("resolved_parameters");
  if (it == p.end()) return {};
  try {
    return toml::parse(it->second);
  } catch (const toml::parse_error&) {
    return {};
  }
}

// A sweep's reference_key beside its reference_values, variant by variant (as report.md).
std::string reference_table(const toml::table& scene, const Json& summary) {
  const Json* variants = lookup(summary, "variants");
  const std::string key = scene["sweep"]["reference_key"].value_or(std::string());
  if (!variants || !variants->is_array() || key.empty()) return "";
  const auto* values = scene["sweep"]["reference_values"].as_array();
  const LayoutEntry* e = find_in_layout(LayoutEntry::Kind::summary, key);
  std::string out = "<table>\n<thead><tr><th>variant</th><th>" + html::escape(e ? e->description : key) +
                    " <code>" + html::escape(key) + "</code></th><th>reference</th></tr></thead>\n<tbody>\n";
  for (std::size_t k = 0; k < variants->size(); ++k) {
    const Json& v = (*variants)[k];
    const Json* ours = v.contains("summary") ? lookup(v["summary"], key) : nullptr;
    const std::string ref = values && k < values->size() ? (*values)[k].value_or(std::string()) : "";
    out += "<tr><td>" + html::escape(v.value("label", "")) + "</td><td class=\"value\">" +
           html::escape(ours ? value_text(*ours) : "—") + "</td><td>" +
           html::escape(ref.empty() ? "—" : ref) + "</td></tr>\n";
  }
  out += "</tbody>\n</table>\n";
  const std::string source = scene["sweep"]["reference_source"].value_or(std::string());
  return source.empty() ? out : out + "<p class=\"muted\">Reference: " + html::escape(source) + "</p>\n";
}

std::string animation_section(const fs::path& dir) {
  const fs::path mp4 = dir / "animation.mp4", gif = dir / "animation.gif", poster = dir / "animation.png";
  std::string media;
  if (fs::exists(mp4) && fs::file_size(mp4) <= kLargestEmbeddedMovie) {
    media = "<video controls loop muted playsinline" +
            (fs::exists(poster) ? " poster=\"" + html::data_uri(poster, "image/png") + "\"" : std::string()) +
            "><source src=\"" + html::data_uri(mp4, "video/mp4") + "\" type=\"video/mp4\"></video>\n";
  } else if (fs::exists(gif) && fs::file_size(gif) <= kLargestEmbeddedMovie) {
    media = "<img alt=\"the animation\" src=\"" + html::data_uri(gif, "image/gif") + "\">\n";
  } else {
    return "";
  }
  return "<h2 id=\"animation\">Animation</h2>\n<figure>\n" + media +
         "<figcaption>Left: the particles as dots (each cluster one dot, coloured by its mass) over every "
         "solver's velocity and density at the same time; right: space-time, the density of the exact "
         "solver (else the first) with the paths of the heaviest clusters. Drawn from result.h5 by "
         "<code>shockgas animate</code>.</figcaption>\n</figure>\n";
}

// The plots drawn; where the plotting script failed (plots.log, plots.hpp),
// a run that promised plots says that some may be missing, and why.
std::string plots_section(const fs::path& dir) {
  std::vector<fs::path> pngs;
  for (const auto& f : fs::directory_iterator(dir))
    if (f.path().extension() == ".png" && f.path().filename() != "animation.png") pngs.push_back(f.path());
  const bool failed = fs::exists(dir / "plots.log");
  if (pngs.empty() && !failed) return "";
  std::sort(pngs.begin(), pngs.end());
  std::string out = "<h2 id=\"plots\">Plots</h2>\n";
  if (failed)
    out += "<p class=\"warning\">The plotting script failed: " + std::to_string(pngs.size()) + " picture" +
           (pngs.size() == 1 ? " was" : "s were") +
           " drawn before it stopped, and the others are missing. What it said is kept in "
           "<code>plots.log</code> beside this report.</p>\n";
  for (const auto& png : pngs) {
    const std::string caption = html::png_title(png).value_or(png.stem().string());
    out += "<figure>\n<img alt=\"" + html::escape(caption) + "\" src=\"" + html::data_uri(png, "image/png") +
           "\">\n<figcaption>" + html::escape(caption) + " <span class=\"muted\">(" +
           png.filename().string() + ")</span></figcaption>\n</figure>\n";
  }
  return out;
}

std::string variants_section(const fs::path& dir, const Json& summary) {
  const Json* variants = lookup(summary, "variants");
  if (!variants || !variants->is_array()) return "";
  std::string out = "<h2 id=\"variants\">Variants</h2>\n";
  for (const auto& v : *variants) {
    const std::string sub = v.value("directory", "");
    out += "<h3>" + html::escape(v.value("label", "")) + "</h3>\n<p><code>" +
           html::escape(v.value("set", "")) + "</code>";
    if (fs::exists(dir / sub / "report.html"))
      out += " — <a href=\"" + html::escape(sub) + "/report.html\">its own report</a>";
    out += "</p>\n<details><summary>its figures of merit</summary>\n" +
           figures_table(v.value("summary", Json())) + "</details>\n";
  }
  return out;
}

// build: summary.json's (the instruction set compiled for), not in result.h5.
std::string scene_section(const std::map<std::string, std::string>& p, const std::string& build) {
  auto get = [&p](const char* name) {
    const auto it = p.find(name);
    return it == p.end() ? std::string() : it->second;
  };
  std::string out = "<h2 id=\"scene\">Scene</h2>\n";
  if (!get("overrides").empty())
    out += "<p>Overrides: <code>" + html::escape(get("overrides")) + "</code></p>\n";
  out += "<pre>" + html::escape(get("scene_text")) + "</pre>\n";
  out += "<details><summary>every parameter as run (defaults and overrides resolved)</summary>\n<pre>" +
         html::escape(get("resolved_parameters")) + "</pre>\n</details>\n";
  out += "<h2 id=\"provenance\">Provenance</h2>\n<table>\n<tbody>\n";
  for (const char* name : {"shockgas_version", "git_commit", "created_utc", "scene_path"})
    out += "<tr><th>" + std::string(name) + "</th><td>" + html::escape(get(name)) + "</td></tr>\n";
  if (!build.empty()) out += "<tr><th>build</th><td>" + html::escape(build) + "</td></tr>\n";
  return out + "</tbody>\n</table>\n";
}

FileProblem damaged_summary(const fs::path& dir, const std::string& detail) {
  return FileProblem("summary.json", (dir / "summary.json").string(), "damaged", detail);
}

Json read_summary(const fs::path& dir) {
  std::ifstream in(dir / "summary.json");
  if (!in) throw RunError("report.html: no summary.json in " + dir.string());
  Json summary;
  try {
    summary = Json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw damaged_summary(
        dir, "not JSON as a run writes it (a syntax error at byte " + std::to_string(e.byte) + ")");
  }
  if (!summary.is_object()) throw damaged_summary(dir, "not a JSON object, as a run writes it");
  return summary;
}

void write_report_html_of(const fs::path& dir, const Json& summary, const ResultContents& h5) {
  const auto p = provenance(h5);
  const toml::table scene = resolved(p);
  const std::string name = p.count("scene_name") ? p.at("scene_name") : summary.value("scene", "");
  std::string body = "<header>\n<h1>" + html::escape(name) + "</h1>\n";
  if (const std::string d = scene["scene"]["description"].value_or(std::string()); !d.empty())
    body += "<p class=\"lead\">" + html::escape(d) + "</p>\n";
  const std::string animation = animation_section(dir), plots = plots_section(dir);
  body += "<nav>" + std::string(animation.empty() ? "" : "<a href=\"#animation\">animation</a>") +
          "<a href=\"#figures\">figures of merit</a>" +
          (plots.empty() ? "" : "<a href=\"#plots\">plots</a>") +
          "<a href=\"#scene\">scene</a><a href=\"#provenance\">provenance</a></nav>\n</header>\n";
  body += animation;
  body +=
      "<h2 id=\"figures\">Figures of merit</h2>\n<p class=\"muted\">Each value with what it means and what "
      "theory says it should be (docs/output.md).</p>\n" +
      figures_table(summary) + reference_table(scene, summary) + variants_section(dir, summary);
  body += plots + scene_section(p, summary.value("build", std::string()));
  // In place in a finished run's directory (`shockgas animate`): whole or not at all.
  replace_file(dir / "report.html", html::page("shockgas: " + name, body));
}

}  // namespace

void write_report_html(const fs::path& dir) {
  try {
    write_report_html_of(dir, read_summary(dir), read_result(dir / "result.h5"));
  } catch (const nlohmann::json::exception&) {  // a value of another kind than a run writes
    throw damaged_summary(dir, "a value is not of the kind a run writes");
  }
}

void write_report_html(const fs::path& dir, const Json& summary, const ResultContents& h5) {
  // As summary.json holds it: JSON has no infinity or NaN, which it writes as null.
  write_report_html_of(dir, Json::parse(summary.dump()), h5);
}

}  // namespace shockgas::app
