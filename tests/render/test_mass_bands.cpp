#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numeric>

#include "render/image_compare.h"
#include "render/mass_bands.h"
#include "render/offscreen_view.h"
#include "render_test_support.h"

namespace sedem {
namespace {

// Particles on a fine lattice in the three inset windows (top, middle, bottom) and coarse
// elsewhere; the lattice thins out with time so the panels differ.
render::ColumnState column_state(double time, int sample) {
  render::ColumnState s;
  s.time_s = time;
  const int bands = 40;
  for (int k = 0; k < bands; ++k) {
    const double depth = (k + 0.5) / bands;
    s.band_mass_fraction.push_back(
        std::exp(-std::pow(depth - 0.2 - 0.002 * time, 2) / (0.02 + 0.01 * sample)));
  }
  const double total =
      std::accumulate(s.band_mass_fraction.begin(), s.band_mass_fraction.end(), 0.0);
  for (auto& f : s.band_mass_fraction) f /= total;
  const double H = 0.457;
  const double centres[] = {H - 0.003, 0.5 * H, 0.001};
  const double pitch[] = {250e-6, 300e-6, 150e-6};
  for (int w = 0; w < 3; ++w) {
    for (int i = -12; i <= 12; ++i) {
      for (int j = -12; j <= 12; ++j) {
        const double y = centres[w] + j * pitch[w];
        if (y < 0 || y > H || (i + j + int(time / 100)) % 3 == 0) continue;
        s.particles.x.push_back(i * pitch[w]);
        s.particles.y.push_back(y);
        s.particles.diameter.push_back((i * i + j) % 3 == 0 ? 60e-6 : (j % 2 ? 20e-6 : 5e-6));
      }
    }
  }
  return s;
}

render::MassBandsFigure bands_figure() {
  render::MassBandsFigure f;
  f.title = "Mass in the column";
  for (int k = 1; k <= 2; ++k) {
    render::ColumnSample s;
    s.label = "sample " + std::to_string(k);
    s.states = {column_state(60.0, k), column_state(300.0, k)};
    f.samples.push_back(s);
  }
  return f;
}

TEST(MassBands, MatchesBaseline) {
  auto image = render::render_mass_bands(bands_figure());
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 2 * 230 + 110);
  EXPECT_EQ(dims[1], 2 * 380 + 34);
  auto result =
      render::compare_with_baseline(image, test::baseline("mass_bands.png"), test::output_dir());
  EXPECT_TRUE(result.passed) << result.message;
}

TEST(MassBands, DarkestBandIsTheLargestShare) {
  // One panel, one band holding everything and one holding nothing: black and white.
  render::MassBandsFigure f;
  f.samples = {{"s", {render::ColumnState{}}}};
  f.samples[0].states[0].band_mass_fraction = {0.0, 1.0};
  f.insets.clear();
  auto image = render::render_mass_bands(f);
  const double col_x = 14 + 0.5 * 0.0635 * (380 - 42) / 0.457;  // middle of the column
  auto grey_at = [&](double y) {
    return int(*static_cast<unsigned char*>(image->GetScalarPointer(int(col_x), int(y), 0)));
  };
  EXPECT_EQ(grey_at(12 + 0.75 * (380 - 42)), 255);  // upper band: no mass
  EXPECT_EQ(grey_at(12 + 0.25 * (380 - 42)), 0);    // lower band: all of it
}

TEST(MassBands, BandsFromLayersAndParticles) {
  const std::vector<double> layers(250, 2.0);
  const auto bands = render::band_fractions_from_layers(layers, 100);
  ASSERT_EQ(bands.size(), 3u);
  EXPECT_DOUBLE_EQ(bands[0], 0.4);
  EXPECT_DOUBLE_EQ(bands[2], 0.2);

  Particles p;
  p.resize(3);
  p.y = {0.9, 0.1, 0.15};  // one near the top, two near the bottom of a 1 m column
  p.diameter = {2e-6, 1e-6, 1e-6};
  p.weight = {1.0, 4.0, 4.0};
  const auto f = render::band_fractions_from_particles(p, 1.0, 4);
  ASSERT_EQ(f.size(), 4u);
  EXPECT_DOUBLE_EQ(f[0], 8.0 / 16.0);  // 1 x 2^3 against 2 x 4 x 1^3
  EXPECT_DOUBLE_EQ(f[3], 8.0 / 16.0);
  EXPECT_DOUBLE_EQ(f[1] + f[2], 0.0);
}

TEST(MassBands, CsvListsEveryBand) {
  const auto base = test::output_dir() / "mass_bands" / "fig11";
  render::write_mass_bands(bands_figure(), base);
  std::ifstream in(test::output_dir() / "mass_bands" / "fig11.csv");
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header.substr(0, 62), "sample 1 t=60 s:band_top_depth_m,sample 1 t=60 s:mass_percent,");
  EXPECT_NE(header.find("sample 2 t=300 s:mass_percent"), std::string::npos) << header;
  int rows = 0;
  double sum = 0;
  while (std::getline(in, line)) {
    ++rows;
    sum += std::stod(line.substr(line.find(',') + 1));
  }
  EXPECT_EQ(rows, 40);
  EXPECT_NEAR(sum, 100.0, 1e-6);
  EXPECT_TRUE(std::filesystem::exists(test::output_dir() / "mass_bands" / "fig11.png"));
}

}  // namespace
}  // namespace sedem
