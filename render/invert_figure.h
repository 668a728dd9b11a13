#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "render/plot.h"

namespace sedem::render {

// `sedem invert`'s figure: the inverted grading curve with its band beside the standard
// reduction of the same readings (and the true curve when it is known).
struct InvertFigureInput {
  std::string title;
  std::vector<double> diameter_m;  // the inverted curve's nodes
  std::vector<double> percent_finer, lower, upper;
  std::string band_name = "band";  // e.g. "90 % band"
  // What the readings alone allow (InvertedCurve::bound_*); empty: none.
  std::vector<double> bound_diameter_m, bound_lower, bound_upper;
  // Nodes where the readings cannot tell the curve (InvertedCurve::open), marked apart.
  std::vector<double> open_diameter_m, open_percent_finer;
  std::string standard_name;  // e.g. "ASTM D422"
  std::vector<double> standard_diameter_m, standard_percent_finer;
  std::vector<double> true_diameter_m, true_percent_finer;  // empty: unknown
  std::string csv_note;  // a comment line above the CSV's header (a partial run's); empty: none
};

Figure invert_figure(const InvertFigureInput& input);

// Writes `<base>.png` and `<base>.csv`.
void write_invert_figure(const InvertFigureInput& input, const std::filesystem::path& base);

}  // namespace sedem::render
