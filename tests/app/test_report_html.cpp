// report.html (shockgas/app/report/report_html.hpp): every summary key with its declared
// meaning and theory, nothing fetched from outside, a sweep's reference table;
// and the pieces of the page (shockgas/app/report/html_page.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "run_command.hpp"
#include "shockgas/app/output/output_layout.hpp"
#include "shockgas/app/report/html_page.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;
using testing_support::run;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path run_scene(const std::string& name, const std::string& scene) {
  const fs::path dir = testing_support::fresh_process_directory("shockgas-test-html-", name);
  std::ofstream(dir / "scene.toml") << scene;
  EXPECT_EQ(run({"run", (dir / "scene.toml").string(), "--out", (dir / "out").string(), "-q", "--no-plots"}),
            0);
  return dir / "out";
}

// The theory cell of the row of summary key `key`.
std::string theory_cell(const std::string& page, const std::string& key) {
  const auto at = page.find("<code>" + key + "</code>");
  const auto cell = page.rfind("<td class=\"theory\"", at);
  if (at == std::string::npos || cell == std::string::npos) return "no row for " + key;
  return page.substr(cell, page.find("</td>", cell) - cell);
}

const char* kGas =
    "[scene]\ndescription = \"a gas & its <shocks>\"\n[initial]\nN = 400\n[particles]\nr = 0.9\nt_end = "
    "2000\n"
    "samples = 60\n[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 400\n[compare]\nfit_window = 2\n";

TEST(ReportHtml, ShowsEverySummaryKeyWithItsMeaningAndTheory) {
  const fs::path out = run_scene("gas", kGas);
  const std::string page = read_file(out / "report.html");
  EXPECT_NE(page.find("a gas &amp; its &lt;shocks&gt;"), std::string::npos);  // the description, escaped
  for (const char* key :
       {"analysis.T_exponent", "compare.matched_mass_fraction", "continuum.hopf_lax.mass_drift"}) {
    EXPECT_NE(page.find(std::string("<code>") + key + "</code>"), std::string::npos) << key;
    const LayoutEntry* e = find_in_layout(LayoutEntry::Kind::summary, key);
    ASSERT_TRUE(e);
    EXPECT_NE(page.find(html::escape(e->description)), std::string::npos) << key;
  }
  // a property of the numerics holds for every scene
  EXPECT_NE(theory_cell(page, "continuum.hopf_lax.mass_drift").find("0 (conservative schemes)"),
            std::string::npos);
  // a theory that names another key shows that key's value where its law holds: t_dissip ~ 1/eps
  // = 20 at r = 0.9 >= 7/9 (theory.crossovers)
  EXPECT_NE(theory_cell(page, "analysis.t_dissip").find("data-laws=\"crossovers\">~ 20 time"),
            std::string::npos);
  // and none where it does not: T ~ t^(-2/3) from 10 t_stick = 10 eps^(-3/2) = 894 to N^(3/2) / 10 = 800,
  // no window for 400 particles (T is fitted on [1000, 2000], after 10 t_stick, with no theory)
  EXPECT_NE(theory_cell(page, "analysis.T_exponent")
                .find("data-refused=\"sticky_cooling\">no theory for this scene"),
            std::string::npos);
  // the provenance carries the build summary.json records (it was left out)
  EXPECT_NE(page.find("<tr><th>build</th><td>" + html::escape(kBuildTarget) + "</td></tr>"),
            std::string::npos);
  // nothing but what it carries: no address to fetch, and a policy refusing any
  EXPECT_EQ(page.find("://"), std::string::npos);
  EXPECT_EQ(page.find(" src=\"data:"), std::string::npos);  // --no-plots: no picture to embed
  EXPECT_NE(page.find("default-src 'none'"), std::string::npos);
}

// The sticky gas (r = 0) has no elastic or homogeneous-cooling regime: no crossover times and
// no -2 plateau are stated for it, while its cooling law is.
TEST(ReportHtml, StatesATheoryOnlyWhereItsLawHolds) {
  const fs::path out =
      run_scene("sticky",
                "[initial]\nN = 400\n[particles]\nr = 0\nt_end = 100\nsamples = 10\n[continuum]\n"
                "solvers = [\"hopf_lax\"]\ncells = 400\n");
  const std::string page = read_file(out / "report.html");
  for (const char* key : {"analysis.t_dissip", "analysis.t_stick", "analysis.t_dissip_theory",
                          "analysis.t_stick_theory", "analysis.T_steepest_local_exponent"})
    EXPECT_NE(theory_cell(page, key).find("data-refused=\"crossovers\">no theory for this scene"),
              std::string::npos)
        << key << ": " << theory_cell(page, key);
  // T ~ t^(-2/3) holds from 10 t_stick: at r = 0 (t_stick = 2^(3/2)) on [100 / fit_window, 100]
  EXPECT_NE(theory_cell(page, "analysis.T_exponent").find("data-laws=\"sticky_cooling\">-2/3"),
            std::string::npos)
      << theory_cell(page, "analysis.T_exponent");
}

TEST(ReportHtml, SweepSetsItsResultBesideTheReference) {
  const fs::path out = run_scene(
      "sweep",
      "[initial]\nN = 200\n[particles]\nt_end = 20\nsamples = 6\n[sweep]\nvariants = [\"particles.r=0.5\", "
      "\"particles.r=0.9\"]\nreference_key = \"particles.stop\"\nreference_values = [\"completed\", \"\"]\n");
  const std::string page = read_file(out / "report.html");
  EXPECT_NE(page.find("<td class=\"value\">completed</td><td>completed</td>"), std::string::npos);
  EXPECT_NE(page.find("<td class=\"value\">completed</td><td>—</td>"), std::string::npos);
  EXPECT_NE(page.find("href=\"0-particles.r_0.5/report.html\""), std::string::npos);
}

TEST(HtmlPage, EscapesAndEmbeds) {
  EXPECT_EQ(html::escape("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
  const fs::path file = testing_support::process_temp_path("shockgas-test-html-", "bytes");
  std::ofstream(file, std::ios::binary) << "Man";  // the base64 textbook example
  EXPECT_EQ(html::data_uri(file, "text/plain"), "data:text/plain;base64,TWFu");
  std::ofstream(file, std::ios::binary) << "Ma";
  EXPECT_EQ(html::data_uri(file, "text/plain"), "data:text/plain;base64,TWE=");
  fs::remove(file);
}

TEST(HtmlPage, ReadsThePngTitle) {
  // A PNG's signature, then a tEXt chunk "Title\0..." (the CRC is not checked), then IEND.
  auto chunk = [](const std::string& type, const std::string& data) {
    std::string c;
    for (int shift : {24, 16, 8, 0}) c += static_cast<char>((data.size() >> shift) & 0xff);
    return c + type + data + std::string(4, '\0');
  };
  const fs::path png = testing_support::process_temp_path("shockgas-test-html-", "title.png");
  std::ofstream(png, std::ios::binary)
      << std::string("\x89PNG\r\n\x1a\n", 8) << chunk("tEXt", std::string("Title\0fields at t = 1", 21))
      << chunk("IEND", "");
  EXPECT_EQ(html::png_title(png).value_or("(none)"), "fields at t = 1");
  // A title beyond Latin-1 (plain Unicode for what mathtext drew): matplotlib writes an
  // uncompressed iTXt, "Title\0" flag 0, method 0, language "", translated keyword "", UTF-8.
  const std::string unicode = "temperature T = \u27e8v\u00b2\u27e9";
  std::ofstream(png, std::ios::binary)
      << std::string("\x89PNG\r\n\x1a\n", 8) << chunk("iTXt", std::string("Title\0\0\0\0\0", 10) + unicode)
      << chunk("IEND", "");
  EXPECT_EQ(html::png_title(png).value_or("(none)"), unicode);
  std::ofstream(png, std::ios::binary) << std::string("\x89PNG\r\n\x1a\n", 8) << chunk("IEND", "");
  EXPECT_FALSE(html::png_title(png));
  fs::remove(png);
}

}  // namespace
}  // namespace shockgas::app
