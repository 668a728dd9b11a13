#include "app/batch_index.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/batch_summary.h"
#include "app/html_text.h"
#include "app/report_images.h"
#include "app/report_page.h"
#include "app/run_report.h"
#include "render/atomic_write.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

std::string cell(double x, const char* format) {
  if (std::isnan(x)) return "<td class=\"num\">-</td>";
  char text[48];
  std::snprintf(text, sizeof text, format, x);
  return std::string("<td class=\"num\">") + text + "</td>";
}

std::string runs_table(const std::vector<BatchRun>& runs, const std::string& sweep_key,
                       const fs::path& out_dir) {
  const bool seeds = std::any_of(runs.begin(), runs.end(), [](const auto& r) { return r.seed; });
  // Two header rows: each test over its error and bias.
  const std::string span = std::string(" rowspan=\"2\"");
  std::string html =
      "<div class=\"wide\"><table class=\"runs\">\n<thead><tr><th" + span + ">run</th>";
  if (!sweep_key.empty()) html += "<th" + span + ">" + html_escape(sweep_key) + "</th>";
  if (seeds) html += "<th" + span + ">seed</th>";
  for (const auto& test : batch_tests()) html += "<th colspan=\"2\">" + test + " (pp)</th>";
  html += "<th" + span + ">wall time (s)</th><th" + span + ">particles</th><th" + span +
          ">status</th></tr>\n<tr>";
  for (std::size_t i = 0; i < batch_tests().size(); ++i) html += "<th>error</th><th>bias</th>";
  html += "</tr></thead>\n<tbody>\n";
  for (const auto& r : runs) {
    const auto record = read_run_record(out_dir / r.folder);
    const bool has_report = fs::exists(out_dir / r.folder / kRunReport);
    const std::string target = r.folder + (has_report ? std::string("/") + kRunReport : "");
    html += "<tr><td><a href=\"" + url_path(target) + "\">" + html_escape(r.folder) + "</a></td>";
    if (!sweep_key.empty()) html += "<td>" + html_escape(r.value) + "</td>";
    if (seeds) html += "<td class=\"num\">" + (r.seed ? std::to_string(*r.seed) : "") + "</td>";
    for (const auto& test : batch_tests())
      html += cell(run_figure(record, test, "error_pp"), "%.2f") +
              cell(run_figure(record, test, "bias_pp"), "%.2f");
    auto number = [&](const char* key) {
      return record.is_object() && record.contains(key) && record[key].is_number()
                 ? record[key].get<double>()
                 : NAN;
    };
    html += cell(number("wall_time_s"), "%.1f") + cell(number("particle_count"), "%.0f");
    const std::string status =
        record.is_object() && record.contains("status") && record["status"].is_string()
            ? record["status"].get<std::string>()
            : "missing";
    html +=
        status == "complete"
            ? "<td><span class=\"status complete\">complete</span></td>"
            : "<td><span class=\"status partial\">partial: " + html_escape(status) + "</span></td>";
    html += "</tr>\n";
  }
  return html + "</tbody>\n</table></div>\n";
}

}  // namespace

void write_batch_index(const std::vector<BatchRun>& runs, const std::string& sweep_key,
                       const fs::path& out_dir) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(out_dir))
    if (e.is_regular_file() && e.path().extension() != ".tmp" &&
        e.path().filename() != "index.html")
      files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  const auto complete = std::count_if(runs.begin(), runs.end(), [&](const auto& r) {
    const auto record = read_run_record(out_dir / r.folder);
    return record.is_object() && record.value("status", "") == "complete";
  });

  std::string body = "<h1>sedem batch</h1>\n<p>" + std::to_string(runs.size()) + " runs";
  if (!sweep_key.empty()) body += " over <code>" + html_escape(sweep_key) + "</code>";
  body += ", " + std::to_string(complete) + " complete";
  if (std::size_t(complete) < runs.size())
    body += "; <span class=\"status partial\">partial: " +
            std::to_string(runs.size() - std::size_t(complete)) + " did not complete</span>";
  body += ". Each run's name links to its report.</p>\n";
  body += "<section id=\"runs\">\n<h2>Runs</h2>\n" + runs_table(runs, sweep_key, out_dir) +
          "<p class=\"note\">Error and bias in percentage points of percent finer; \"-\": the "
          "run has no such number (see its report).</p>\n</section>\n";
  const auto figures = find_figures(files, "");
  if (!figures.empty()) {
    body += "<section id=\"figures\">\n<h2>Summary figures</h2>\n";
    for (const auto& f : figures) body += figure_html(f);
    body += "</section>\n";
  }
  body += "<section id=\"files\">\n<h2>Files</h2>\n<ul class=\"files\">\n";
  for (const auto& f : files)
    if (fs::path(f).extension() == ".csv")
      body += "<li><a href=\"" + url_path(f) + "\">" + html_escape(f) + "</a></li>\n";
  body += "</ul>\n</section>\n";
  const std::string html = html_page("sedem batch", body);
  write_atomically(out_dir / "index.html", [&](std::ostream& out) { out << html; });
}

}  // namespace sedem::app
