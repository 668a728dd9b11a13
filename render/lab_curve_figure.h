#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/lab/whole_curve.h"
#include "render/plot.h"

namespace sedem::render {

// A laboratory's grading curve as its report draws it: percent finer against the diameter in
// mm on a log axis, one series per source (the sieves, the hydrometer's reduction, an
// inversion), each drawn as points joined by a line.
Figure lab_curve_figure(const std::string& title, const std::vector<CurvePoint>& curve);

// Writes `<base>.png` and `<base>.csv`.
void write_lab_curve_figure(const std::string& title, const std::vector<CurvePoint>& curve,
                            const std::filesystem::path& base);

}  // namespace sedem::render
