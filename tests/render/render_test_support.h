#pragma once

#include <filesystem>

#include <vtkImageData.h>

#include "core/model/snapshot.h"

#include "render/drawing/figure_files.h"
#include "render/series_reader.h"

namespace sedem::test {

inline std::filesystem::path baseline(const char* name) {
  return std::filesystem::path(SEDEM_SOURCE_DIR) / "tests" / "baselines" / name;
}
inline std::filesystem::path output_dir() {
  return SEDEM_TEST_OUTPUT;
}

// Every format a figure can be written in.
inline const render::FigureOutput kEveryFormat = [] {
  render::FigureOutput output;
  output.formats = {render::FigureFormat::png, render::FigureFormat::svg,
                    render::FigureFormat::pdf};
  return output;
}();

// A fixed, hand-made snapshot: a 7 x 20 lattice of three sizes.
inline Snapshot lattice_snapshot() {
  Snapshot s;
  s.time = 42.0;
  auto& p = s.particles;
  p.resize(140);
  for (std::size_t i = 0; i < 140; ++i) {
    p.x[i] = -0.027 + 0.009 * double(i % 7);
    p.y[i] = 0.02 + 0.02 * double(i / 7);
    p.vy[i] = -1e-3 * double(i % 3);
    p.diameter[i] = (i % 3 == 0 ? 5e-6 : i % 3 == 1 ? 20e-6 : 60e-6);
    p.weight[i] = 1.0 + double(i);
    p.size_class[i] = std::int32_t(i % 3);
    p.id[i] = std::uint32_t(i);
  }
  return s;
}

}  // namespace sedem::test

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sedem::test {

// The (timestep, file) entries of a .pvd collection, in file order.
inline std::vector<std::pair<double, std::string>> parse_pvd(const std::filesystem::path& pvd) {
  return render::read_pvd(pvd);
}

// Pixels within 12 levels of one colour in the columns [x0, x1) of an RGB image.
inline int pixels_of(vtkImageData* image, std::array<unsigned char, 3> rgb, int x0, int x1) {
  int dims[3];
  image->GetDimensions(dims);
  int n = 0;
  for (int j = 0; j < dims[1]; ++j)
    for (int i = std::max(x0, 0); i < std::min(x1, dims[0]); ++i) {
      const auto* px = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
      if (std::abs(px[0] - rgb[0]) < 12 && std::abs(px[1] - rgb[1]) < 12 &&
          std::abs(px[2] - rgb[2]) < 12)
        ++n;
    }
  return n;
}

// Dark pixels (every channel below 128: text, lines) in the columns [x0, x1) and rows
// [y0, y1) of an RGB image (rows from the bottom).
inline int dark_pixels(vtkImageData* image, int x0, int x1, int y0, int y1) {
  int dims[3];
  image->GetDimensions(dims);
  int n = 0;
  for (int j = std::max(y0, 0); j < std::min(y1, dims[1]); ++j)
    for (int i = std::max(x0, 0); i < std::min(x1, dims[0]); ++i) {
      const auto* px = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
      if (px[0] < 128 && px[1] < 128 && px[2] < 128) ++n;
    }
  return n;
}

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace sedem::test
