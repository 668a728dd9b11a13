#include "app/run_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "app/html_text.h"
#include "app/progress.h"
#include "app/report_images.h"
#include "app/report_page.h"
#include "render/atomic_write.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

using json = nlohmann::json;

// record[key] when record is an object holding it, else null: a damaged run.json shows "-".
json member(const json& record, const char* key) {
  return record.is_object() && record.contains(key) ? record[key] : json();
}

std::string text_of(const json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_float()) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value.get<double>());
    return text;
  }
  if (value.is_array()) {
    std::string list;
    for (const auto& v : value) list += (list.empty() ? "" : ", ") + text_of(v);
    return "[" + list + "]";
  }
  return value.is_null() ? "-" : value.dump();
}

std::string number(const json& value, const char* format) {
  if (!value.is_number()) return "-";
  char text[48];
  std::snprintf(text, sizeof text, format, value.get<double>());
  return text;
}

std::string row(const std::string& id, const std::string& name, const std::string& html) {
  return "<tr id=\"" + id + "\"><th>" + name + "</th><td>" + html + "</td></tr>\n";
}

// The status line and, for a run that did not complete, why its files are partial.
std::string status_html(const json& record, const fs::path& dir) {
  const std::string status = text_of(member(record, "status"));
  if (status == "complete") return "<p><span class=\"status complete\">complete</span></p>\n";
  const std::string reached = number(member(record, "simulated_time_s"), "%g");
  const std::string end = number(member(member(record, "scene"), "run.end_time_s"), "%g");
  std::string why;
  if (status == "interrupted")
    why = "The run was stopped (Ctrl-C or SIGTERM) at t = " + reached + " s of " + end +
          " s: its files, figures and results stop there. Finish it with <code>sedem run "
          "--resume " +
          html_escape(dir.string()) + "</code>.";
  else if (status == "failed")
    why = "The run failed at t = " + reached + " s of " + end +
          " s: " + html_escape(text_of(member(record, "message"))) +
          ". Its files stop where it did.";
  else
    why = "run.json says \"" + html_escape(status) + "\": the run did not finish (it is going " +
          "on, or was killed); its files stop at t = " + reached + " s of " + end + " s.";
  return "<p><span class=\"status partial\">partial: " + html_escape(status) +
         "</span></p>\n<p class=\"banner\">" + why + "</p>\n";
}

std::string facts_html(const json& record) {
  const json scene = member(record, "scene");
  const json wall = member(record, "wall_time_s");
  const double memory = member(record, "peak_memory_bytes").is_number()
                            ? member(record, "peak_memory_bytes").get<double>()
                            : NAN;
  std::string html = "<table class=\"facts\">\n";
  html += row("version", "version", html_escape(text_of(member(record, "version"))));
  html += row("scene-file", "scene file", html_escape(text_of(member(record, "scene_file"))));
  html += row("seed", "seed", html_escape(text_of(member(record, "seed"))));
  html += row("particles", "particles", html_escape(text_of(member(record, "particle_count"))));
  html += row("simulated", "simulated time",
              number(member(record, "simulated_time_s"), "%g") + " s of " +
                  number(member(scene, "run.end_time_s"), "%g") + " s");
  html +=
      row("wall-time", "wall time",
          wall.is_number() ? clock_text(wall.get<double>()) + " (" + number(wall, "%.1f") + " s)"
                           : "-");
  html += row("steps", "steps", html_escape(text_of(member(record, "steps"))));
  html += row("speed", "particle-steps per second",
              number(member(record, "particle_steps_per_s"), "%.3g"));
  html += row("memory", "peak memory",
              std::isfinite(memory) ? number(memory / (1 << 20), "%.0f") + " MiB" : "-");
  if (member(record, "legs").is_number() && member(record, "legs").get<double>() > 1)
    html += row("legs", "legs", text_of(member(record, "legs")) + " (resumed with --resume)");
  return html + "</table>\n";
}

std::string results_html(const json& record) {
  const json results = member(record, "results");
  if (!results.is_object() || results.empty())
    return "<p>No test results: the run has no instrument, or ended before any was read.</p>\n";
  std::string html =
      "<table class=\"results\">\n<thead><tr><th>test</th><th>error (pp)</th><th>bias "
      "(pp)</th><th>readings</th><th>note</th></tr></thead>\n<tbody>\n";
  std::vector<std::string> tests{"hydrometer", "buoyancy", "pipette"};
  for (const auto& [test, r] : results.items())
    if (std::find(tests.begin(), tests.end(), test) == tests.end()) tests.push_back(test);
  for (const auto& test : tests) {
    if (!results.contains(test)) continue;
    const json r = results[test];
    std::string note = html_escape(member(r, "note").is_string() ? text_of(member(r, "note")) : "");
    if (const json off = member(r, "off_scale_readings"); off.is_number() && off.get<double>() > 0)
      note += (note.empty() ? "" : "; ") + text_of(off) +
              " reading(s) off the 152H scale (-5 to 60 g/L) or with the bulb out of the liquid: "
              "see on_scale in readings_hydrometer.csv";
    html += "<tr id=\"result-" + html_escape(test) + "\"><th>" + html_escape(test) +
            "</th><td class=\"num\">" + number(member(r, "error_pp"), "%.2f") +
            "</td><td class=\"num\">" + number(member(r, "bias_pp"), "%.2f") +
            "</td><td class=\"num\">" + html_escape(text_of(member(r, "readings"))) + "</td><td>" +
            note + "</td></tr>\n";
  }
  return html +
         "</tbody>\n</table>\n<p class=\"note\">In percentage points of percent finer. Error: "
         "the test from the DEM against the reference solution (what the simulation gets "
         "wrong); bias: the reference solution against the true curve (what the laboratory test "
         "itself gets wrong). \"-\": no number, for the reason in the note.</p>\n";
}

// What makes the results doubtful though every value is in range (run.json's "warnings"),
// above the results they qualify; nothing when there is none.
std::string warnings_html(const json& record) {
  const json warnings = member(record, "warnings");
  if (!warnings.is_array() || warnings.empty()) return "";
  std::string html = "<div class=\"warnings\" id=\"warnings\"><strong>Warnings</strong><ul>\n";
  for (const auto& w : warnings) {
    const json message = w.is_object() ? member(w, "message") : w;
    html += "<li>" + html_escape(text_of(message)) + "</li>\n";
  }
  return html + "</ul></div>\n";
}

// Links to the run's data: CSVs, ParaView series (with the count of files each holds), the
// record; the files of other folders counted.
std::string files_html(const std::vector<std::string>& files) {
  std::map<std::string, std::size_t> in_folder;
  std::vector<std::string> csv, series, other{"run.json"};
  for (const auto& f : files) {
    const auto slash = f.find('/');
    if (slash != std::string::npos) {
      ++in_folder[f.substr(0, slash)];
      continue;
    }
    const std::string ext = fs::path(f).extension().string();
    if (f == kRunReport) continue;
    (ext == ".csv" ? csv : ext == ".pvd" ? series : other).push_back(f);
  }
  auto list = [](const std::vector<std::string>& names, auto&& detail) {
    std::string html = "<ul class=\"files\">\n";
    for (const auto& n : names)
      html +=
          "<li><a href=\"" + url_path(n) + "\">" + html_escape(n) + "</a>" + detail(n) + "</li>\n";
    return html + "</ul>\n";
  };
  auto none = [](const std::string&) { return std::string(); };
  std::string html;
  if (!csv.empty()) html += "<h3>Readings and curves (CSV)</h3>\n" + list(csv, none);
  if (!series.empty()) {
    html += "<h3>ParaView series</h3>\n" + list(series, [&](const std::string& pvd) {
              const std::string folder = fs::path(pvd).stem().string();
              const auto n = in_folder.count(folder) ? in_folder[folder] : 0;
              return n ? " (" + std::to_string(n) + (n == 1 ? " file in " : " files in ") +
                             html_escape(folder) + "/)"
                       : std::string();
            });
    html +=
        "<p class=\"note\">Open a <code>.pvd</code> in ParaView for the series over time "
        "(docs/paraview.md).</p>\n";
  }
  html += "<h3>Run record</h3>\n" + list(other, none);
  std::string folders;
  for (const auto& [folder, n] : in_folder)
    folders += (folders.empty() ? "" : ", ") + html_escape(folder) + "/ (" + std::to_string(n) +
               (n == 1 ? " file)" : " files)");
  if (!folders.empty()) html += "<p class=\"note\">Folders: " + folders + ".</p>\n";
  return html;
}

// Every key of the scene as resolved, grouped by its first part.
std::string scene_html(const json& record) {
  const json scene = member(record, "scene");
  if (!scene.is_object()) return "<p>run.json holds no scene.</p>\n";
  std::string html =
      "<table class=\"scene\">\n<thead><tr><th>key</th><th>value</th></tr></thead>\n";
  std::string group = "\n";
  for (const auto& [key, value] : scene.items()) {
    const std::string first = key.substr(0, key.find('.'));
    if (key.find('.') != std::string::npos && first != group)
      html += "<tr><th class=\"group\" colspan=\"2\">" + html_escape(first) + "</th></tr>\n";
    group = key.find('.') != std::string::npos ? first : "\n";
    html += "<tr><td><code>" + html_escape(key) + "</code></td><td>" + html_escape(text_of(value)) +
            "</td></tr>\n";
  }
  return html + "</table>\n";
}

}  // namespace

std::string run_report_html(const json& record, const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& f : member(record, "files"))
    if (f.is_string()) files.push_back(f.get<std::string>());
  const std::string name = text_of(member(member(record, "scene"), "name"));
  const auto figures = find_figures(files, "figures/");
  const std::string frames = frames_html(files);

  std::string body = "<h1>sedem run: " + html_escape(name) + "</h1>\n";
  body += "<nav><a href=\"#results\">error and bias</a>";
  if (!figures.empty()) body += "<a href=\"#figures\">figures</a>";
  if (!frames.empty()) body += "<a href=\"#frames\">frames</a>";
  body += "<a href=\"#files\">files</a><a href=\"#scene\">scene</a></nav>\n";
  body += status_html(record, dir) + facts_html(record);
  body += "<section id=\"results\">\n<h2>Error and bias</h2>\n" + warnings_html(record) +
          results_html(record) + "</section>\n";
  if (!figures.empty()) {
    body += "<section id=\"figures\">\n<h2>Figures</h2>\n";
    for (const auto& f : figures) body += figure_html(f);
    body += "</section>\n";
  }
  if (!frames.empty())
    body += "<section id=\"frames\">\n<h2>The column over time</h2>\n" + frames + "</section>\n";
  body += "<section id=\"files\">\n<h2>Files</h2>\n" + files_html(files) + "</section>\n";
  body +=
      "<section id=\"scene\">\n<h2>Scene as resolved</h2>\n" + scene_html(record) + "</section>\n";
  return html_page("sedem run: " + name, body);
}

void write_run_report(json record, const fs::path& dir) {
  json& files = record["files"];
  if (!files.is_array()) files = json::array();
  if (std::find(files.begin(), files.end(), kRunReport) == files.end()) files.push_back(kRunReport);
  const std::string html = run_report_html(record, dir);
  write_atomically(dir / kRunReport, [&](std::ostream& out) { out << html; });
}

}  // namespace sedem::app
