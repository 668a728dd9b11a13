#include "app/lab_report.h"

#include <cmath>
#include <cstdio>

#include "app/html_text.h"
#include "app/report_images.h"
#include "app/report_page.h"
#include "render/atomic_write.h"

namespace sedem::app {

namespace {

bool numeric(const std::string& cell) {
  return !cell.empty() && cell.find_first_not_of("0123456789.-+e") == std::string::npos;
}

std::string table_html(const LabReportTable& table) {
  std::string html = "<section id=\"" + html_escape(table.id) + "\">\n<h2>" +
                     html_escape(table.heading) + "</h2>\n<div class=\"wide\"><table>\n<thead><tr>";
  for (const auto& c : table.columns) html += "<th>" + html_escape(c) + "</th>";
  html += "</tr></thead>\n<tbody>\n";
  for (const auto& row : table.rows) {
    html += "<tr>";
    for (const auto& cell : row)
      html += (numeric(cell) ? "<td class=\"num\">" : "<td>") + html_escape(cell) + "</td>";
    html += "</tr>\n";
  }
  html += "</tbody>\n</table></div>\n";
  if (!table.note.empty()) html += "<p class=\"note\">" + html_escape(table.note) + "</p>\n";
  return html + "</section>\n";
}

}  // namespace

std::string report_number(double value, int digits) {
  if (std::isnan(value)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

std::string lab_report_html(const LabReport& report) {
  std::string body = "<h1>" + html_escape(report.title) + "</h1>\n";
  body += "<p>Standard followed: <strong id=\"standard\">" + html_escape(report.standard) +
          "</strong></p>\n";
  if (!report.warnings.empty()) {
    body += "<div class=\"warnings\" id=\"warnings\"><strong>Warnings</strong><ul>\n";
    for (const auto& w : report.warnings) body += "<li>" + html_escape(w) + "</li>\n";
    body += "</ul></div>\n";
  }
  body += "<section id=\"inputs\">\n<h2>Inputs</h2>\n<table class=\"facts\">\n";
  for (const auto& [name, value] : report.inputs)
    body += "<tr><th>" + html_escape(name) + "</th><td>" + html_escape(value) + "</td></tr>\n";
  body += "</table>\n</section>\n";
  if (!report.figure_stem.empty()) {
    FigureFiles figure{report.figure_stem, {}};
    figure.formats.insert(report.figure_formats.begin(), report.figure_formats.end());
    body +=
        "<section id=\"curve\">\n<h2>Grading curve</h2>\n" + figure_html(figure) + "</section>\n";
  }
  for (const auto& t : report.tables) body += table_html(t);
  if (!report.files.empty()) {
    body += "<section id=\"files\">\n<h2>Files</h2>\n<ul class=\"files\">\n";
    for (const auto& f : report.files)
      body += "<li><a href=\"" + url_path(f) + "\">" + html_escape(f) + "</a></li>\n";
    body += "</ul>\n</section>\n";
  }
  return html_page(report.title, body);
}

void write_lab_report(const LabReport& report, const std::filesystem::path& file) {
  const std::string html = lab_report_html(report);
  write_atomically(file, [&](std::ostream& out) { out << html; });
}

}  // namespace sedem::app
