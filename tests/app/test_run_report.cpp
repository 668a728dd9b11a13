// report.html and a batch's index.html as text: what they show of a record, escaped, with
// relative links only, whatever formats the figures were written in.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/html_text.h"
#include "app/report_images.h"
#include "app/run_report.h"

namespace sedem {
namespace {

using nlohmann::json;

json record_of(const std::string& status) {
  return {{"status", status},
          {"version", "1.2.3"},
          {"scene_file", "scenes/<demo>.toml"},
          {"scene", {{"name", "a <b>\"c\" & 'd'"}, {"run.end_time_s", 120.0}}},
          {"simulated_time_s", 30.0},
          {"wall_time_s", 75.5},
          {"results",
           {{"hydrometer",
             {{"error_pp", nullptr},
              {"bias_pp", nullptr},
              {"readings", 0},
              {"note", "no readings: the run ended before the test's first reading time"}}},
            {"pipette", {{"error_pp", 1.234}, {"bias_pp", 0.5}, {"readings", 3}}}}},
          {"files",
           {"figures/fig12_largest_diameter.csv", "figures/fig12_largest_diameter.png",
            "figures/fig12_largest_diameter.svg", "figures/fig18_granulometry.png",
            "figures/fig18_granulometry.pdf", "figures/fig19_only.pdf", "frames/column_000000.png",
            "frames/column_000001.png", "particles.pvd", "particles/particles_000000.vtp",
            "readings_pipette.csv", "odd #name.csv"}}};
}

TEST(RunReport, EscapesEveryTextOfTheRecord) {
  const std::string page = app::run_report_html(record_of("complete"), "out/demo");
  EXPECT_EQ(page.find("<b>"), std::string::npos);
  EXPECT_NE(page.find("a &lt;b&gt;&quot;c&quot; &amp; &#39;d&#39;"), std::string::npos);
  EXPECT_NE(page.find("scenes/&lt;demo&gt;.toml"), std::string::npos);
  EXPECT_EQ(app::html_escape("<&>\"'"), "&lt;&amp;&gt;&quot;&#39;");
  EXPECT_EQ(app::url_path("odd #name?.csv"), "odd%20%23name%3F.csv");
}

TEST(RunReport, ShowsAbsentFiguresAsADashWithTheirReason) {
  const std::string page = app::run_report_html(record_of("complete"), "out/demo");
  EXPECT_NE(page.find("<td class=\"num\">-</td><td class=\"num\">-</td>"), std::string::npos);
  EXPECT_NE(page.find("no readings: the run ended before"), std::string::npos);
  EXPECT_NE(page.find("<td class=\"num\">1.23</td>"), std::string::npos);
  EXPECT_NE(page.find("status complete"), std::string::npos);
  EXPECT_EQ(page.find("class=\"status partial"), std::string::npos);
  EXPECT_NE(page.find("1:16 (75.5 s)"), std::string::npos);
}

TEST(RunReport, ShowsTheRunsWarningsAboveItsResults) {
  auto record = record_of("complete");
  EXPECT_EQ(app::run_report_html(record, "out/demo").find("id=\"warnings\""), std::string::npos);
  record["warnings"] = {
      {{"code", "few_particles"}, {"message", "the pipette's volume holds 3 particles <of 1500>"}}};
  const std::string page = app::run_report_html(record, "out/demo");
  const auto warnings = page.find("id=\"warnings\"");
  ASSERT_NE(warnings, std::string::npos);
  EXPECT_NE(page.find("holds 3 particles &lt;of 1500&gt;", warnings), std::string::npos);
  EXPECT_LT(warnings, page.find("<table class=\"results\""));
}

TEST(RunReport, MarksARunThatDidNotCompleteAsPartial) {
  const std::string page = app::run_report_html(record_of("interrupted"), "out/demo");
  EXPECT_NE(page.find("partial: interrupted"), std::string::npos);
  EXPECT_NE(page.find("at t = 30 s of 120 s"), std::string::npos);
  EXPECT_NE(page.find("sedem run --resume out/demo"), std::string::npos);
  json failed = record_of("failed");
  failed["message"] = "writing <x> failed";
  EXPECT_NE(app::run_report_html(failed, "d").find("partial: failed"), std::string::npos);
  EXPECT_NE(app::run_report_html(failed, "d").find("writing &lt;x&gt; failed"), std::string::npos);
}

TEST(RunReport, ShowsEachFigureOnceWhateverItsFormats) {
  const auto figures =
      app::find_figures(record_of("complete")["files"].get<std::vector<std::string>>(), "figures/");
  ASSERT_EQ(figures.size(), 3u);
  EXPECT_EQ(figures[0].stem, "figures/fig12_largest_diameter");
  const std::string both = app::figure_html(figures[0]);
  EXPECT_NE(both.find("<source srcset=\"figures/fig12_largest_diameter.svg\" "
                      "type=\"image/svg+xml\"><img src=\"figures/fig12_largest_diameter.png\""),
            std::string::npos)
      << both;
  EXPECT_NE(both.find("Fig. 12: largest diameter"), std::string::npos);
  EXPECT_NE(both.find(">CSV</a>"), std::string::npos);
  const std::string png = app::figure_html(figures[1]);
  EXPECT_EQ(png.find("<picture>"), std::string::npos);
  EXPECT_NE(png.find("<img src=\"figures/fig18_granulometry.png\""), std::string::npos);
  EXPECT_NE(png.find("href=\"figures/fig18_granulometry.pdf\">PDF</a>"), std::string::npos);
  const std::string pdf = app::figure_html(figures[2]);
  EXPECT_EQ(pdf.find("<img"), std::string::npos);
  EXPECT_NE(pdf.find("href=\"figures/fig19_only.pdf\""), std::string::npos);
}

TEST(RunReport, LinksTheDataAndPlaysTheFrames) {
  const std::string page = app::run_report_html(record_of("complete"), "out/demo");
  EXPECT_NE(page.find("href=\"readings_pipette.csv\""), std::string::npos);
  EXPECT_NE(page.find("href=\"odd%20%23name.csv\""), std::string::npos);
  EXPECT_NE(page.find("href=\"particles.pvd\">particles.pvd</a> (1 file in particles/)"),
            std::string::npos);
  EXPECT_NE(page.find("href=\"run.json\""), std::string::npos);
  EXPECT_NE(page.find("data-frames=\"[&quot;frames/column_000000.png&quot;,&quot;frames/"
                      "column_000001.png&quot;]\""),
            std::string::npos);
  EXPECT_NE(page.find("frame 1 of 2"), std::string::npos);
  // Nothing from elsewhere.
  EXPECT_EQ(page.find("http"), std::string::npos);
  EXPECT_EQ(page.find("src=\"/"), std::string::npos);
}

}  // namespace
}  // namespace sedem
