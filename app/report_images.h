#pragma once

#include <set>
#include <string>
#include <vector>

namespace sedem::app {

// One figure of a folder: its path without extension ("figures/fig18_granulometry") and the
// extensions it is written in ("csv", "pdf", "png", "svg").
struct FigureFiles {
  std::string stem;
  std::set<std::string> formats;
};

// The figures among `files` (paths relative to the page, '/' separated): each stem with a PNG,
// SVG or PDF, directly in `folder` ("figures/"; "" for the page's own folder), in name order.
// Whatever formats were written, each figure is found once.
std::vector<FigureFiles> find_figures(const std::vector<std::string>& files,
                                      const std::string& folder);

// A figure as HTML: the SVG where there is one, with the PNG as its fallback (<picture>), or
// the one picture there is; a caption with its title and a link to each of its files (PDF,
// CSV). A figure written as PDF only is shown as its links.
std::string figure_html(const FigureFiles& figure);

// "Fig. 12: largest diameter" from "figures/fig12_largest_diameter"; other names with their
// underscores as spaces.
std::string figure_title(const std::string& stem);

// The frames among `files` (frames/column_*.png) as a player (the first frame, a play button
// and a slider; app/report_page.cpp's script) and a strip of at most `strip` frames spread
// evenly, each a link to its picture. "" when there are none.
std::string frames_html(const std::vector<std::string>& files, std::size_t strip = 16);

}  // namespace sedem::app
