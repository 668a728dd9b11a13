#include "app/report_images.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "app/html_text.h"

namespace sedem::app {

namespace {

const std::set<std::string> kPictures{"png", "svg", "pdf"};

std::string link(const std::string& path, const std::string& text) {
  return "<a href=\"" + url_path(path) + "\">" + html_escape(text) + "</a>";
}

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::vector<FigureFiles> find_figures(const std::vector<std::string>& files,
                                      const std::string& folder) {
  std::map<std::string, std::set<std::string>> formats;
  for (const auto& f : files) {
    if (f.rfind(folder, 0) != 0) continue;
    const std::string name = f.substr(folder.size());
    const auto dot = name.rfind('.');
    if (name.find('/') != std::string::npos || dot == std::string::npos || dot == 0) continue;
    formats[folder + name.substr(0, dot)].insert(name.substr(dot + 1));
  }
  std::vector<FigureFiles> figures;
  for (auto& [stem, exts] : formats)
    if (std::any_of(exts.begin(), exts.end(), [](const auto& e) { return kPictures.count(e); }))
      figures.push_back({stem, std::move(exts)});
  return figures;
}

std::string figure_title(const std::string& stem) {
  std::string name = stem.substr(stem.rfind('/') == std::string::npos ? 0 : stem.rfind('/') + 1);
  std::string title;
  if (name.size() > 5 && name.rfind("fig", 0) == 0 && std::isdigit((unsigned char)name[3]) &&
      std::isdigit((unsigned char)name[4])) {
    title = "Fig. " + name.substr(3, 2) + (name.size() > 6 ? ": " : "");
    name = name.size() > 6 ? name.substr(6) : "";
  }
  std::replace(name.begin(), name.end(), '_', ' ');
  return title + name;
}

std::string figure_html(const FigureFiles& figure) {
  const std::string& stem = figure.stem;
  const std::string title = figure_title(stem);
  const bool png = figure.formats.count("png") > 0, svg = figure.formats.count("svg") > 0;
  const std::string alt = " alt=\"" + html_escape(title) + "\"";
  std::string picture;
  if (svg && png)
    picture = "<picture><source srcset=\"" + url_path(stem + ".svg") +
              "\" type=\"image/svg+xml\"><img src=\"" + url_path(stem + ".png") + "\"" + alt +
              "></picture>";
  else if (svg || png)
    picture = "<img src=\"" + url_path(stem + (svg ? ".svg" : ".png")) + "\"" + alt + ">";
  std::string html = "<figure id=\"" + html_escape(stem) + "\">\n";
  if (!picture.empty())
    html += "<a href=\"" + url_path(stem + (svg ? ".svg" : ".png")) + "\">" + picture + "</a>\n";
  html += "<figcaption>" + html_escape(title);
  for (const auto& ext : figure.formats) html += " · " + link(stem + "." + ext, upper(ext));
  return html + "</figcaption>\n</figure>\n";
}

std::string frames_html(const std::vector<std::string>& files, std::size_t strip) {
  std::vector<std::string> frames;
  for (const auto& f : files)
    if (f.rfind("frames/column_", 0) == 0 && f.size() > 4 && f.substr(f.size() - 4) == ".png")
      frames.push_back(f);
  if (frames.empty()) return "";
  std::sort(frames.begin(), frames.end());
  std::string list;
  for (const auto& f : frames) list += (list.empty() ? "[\"" : ",\"") + url_path(f) + "\"";
  list += "]";
  const std::string count = std::to_string(frames.size());
  std::string html = "<div class=\"player\" data-frames=\"" + html_escape(list) +
                     "\">\n<img src=\"" + url_path(frames.front()) +
                     "\" alt=\"the column, frame 1\">\n" +
                     "<div class=\"controls\"><button type=\"button\">Play</button>" +
                     "<input type=\"range\" min=\"0\" max=\"" + std::to_string(frames.size() - 1) +
                     "\" value=\"0\" aria-label=\"frame\"><span class=\"frame-label\">frame 1 of " +
                     count + "</span></div>\n</div>\n<div class=\"strip\">\n";
  const std::size_t shown = std::min(strip, frames.size());
  for (std::size_t k = 0; k < shown; ++k) {
    const std::size_t i = shown > 1 ? k * (frames.size() - 1) / (shown - 1) : 0;
    html += "<a href=\"" + url_path(frames[i]) + "\"><img src=\"" + url_path(frames[i]) +
            "\" alt=\"frame " + std::to_string(i + 1) + "\"></a>\n";
  }
  return html + "</div>\n";
}

}  // namespace sedem::app
