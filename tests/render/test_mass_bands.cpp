#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
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
  EXPECT_EQ(dims[0], 2 * 270 + 110);
  EXPECT_EQ(dims[1], 2 * 380 + 34);
  auto result =
      render::compare_with_baseline(image, test::baseline("mass_bands.png"), test::output_dir());
  EXPECT_TRUE(result.passed) << result.message;
}

TEST(MassBands, PanelTitlesStayWithinTheirPanel) {
  // Runs that `sedem render` names by three scene keys: each title in its own panel.
  auto f = bands_figure();
  f.title.clear();
  f.samples[0].label = "integrator.local_steps=true, sample.seed=7, sample.simulated_count=1500";
  f.samples[1].label = "integrator.local_steps=false, sample.seed=8, sample.simulated_count=3000";
  const auto image = render::render_mass_bands(f);
  int dims[3];
  image->GetDimensions(dims);
  const int top = dims[1] - 6, bottom = dims[1] - 24;  // the top row's titles
  EXPECT_EQ(test::dark_pixels(image, 0, 3, bottom, top), 0);
  EXPECT_EQ(test::dark_pixels(image, f.panel_width - 3, f.panel_width + 3, bottom, top), 0);
  EXPECT_GT(test::dark_pixels(image, 0, f.panel_width, bottom, top), 100);
}

TEST(MassBands, SvgHoldsTheColumnAsVectorGraphics) {
  const auto base = test::output_dir() / "mass_bands_vector";
  render::write_mass_bands(bands_figure(), base, test::kEveryFormat);
  auto svg = base;
  svg += ".svg";
  ASSERT_TRUE(std::filesystem::exists(svg));
  const auto text = test::read_text(svg);
  EXPECT_NE(text.find("viewBox=\"0 0 650 794\""), std::string::npos);  // as the PNG
  std::size_t polygons = 0;
  for (auto at = text.find("<polygon"); at != std::string::npos; at = text.find("<polygon", at + 1))
    ++polygons;
  EXPECT_GT(polygons, 4u * 40u);  // every band of the four columns, and the grains
  EXPECT_NE(text.find("<polyline"), std::string::npos);
  EXPECT_NE(text.find(">Mass in the column</text>"), std::string::npos);
  EXPECT_NE(text.find(">sample 2, t = 300 s</text>"), std::string::npos);
  EXPECT_NE(text.find("\u00d7"), std::string::npos);  // the zooms' magnification
}

// The grey at a depth fraction (0 bottom, 1 top) of the only panel's column.
int grey_at(vtkImageData* image, double fraction) {
  const double col_y0 = 26, col_h = 380 - 30 - col_y0;
  const double col_x = 36 + 0.5 * 0.0635 * col_h / 0.457;  // middle of the column
  return int(*static_cast<unsigned char*>(
      image->GetScalarPointer(int(col_x), int(col_y0 + fraction * col_h), 0)));
}

TEST(MassBands, FullScaleIsBlackAndNoMassWhite) {
  // One panel, one band holding everything and one holding nothing: black and white.
  render::MassBandsFigure f;
  f.samples = {{"s", {render::ColumnState{}}}};
  f.samples[0].states[0].band_mass_fraction = {0.0, 1.0};
  f.insets.clear();
  auto image = render::render_mass_bands(f);
  EXPECT_EQ(grey_at(image, 0.75), 255);  // upper band: no mass
  EXPECT_EQ(grey_at(image, 0.25), 0);    // lower band: all of it
}

TEST(MassBands, SuspensionShowsBesideADenseBed) {
  // 60 % of the mass in the bottom band, the rest spread over the 39 above: the scale is not
  // set by the bed (which would leave the suspension white) but by the homogeneous share.
  render::MassBandsFigure f;
  f.samples = {{"s", {render::ColumnState{}}}};
  auto& bands = f.samples[0].states[0].band_mass_fraction;
  bands.assign(40, 0.4 / 39);
  bands.back() = 0.6;
  f.insets.clear();
  EXPECT_DOUBLE_EQ(render::default_full_scale(f), 0.05);
  auto image = render::render_mass_bands(f);
  EXPECT_LT(grey_at(image, 0.5), 215);     // the suspension reads grey
  EXPECT_GT(grey_at(image, 0.5), 150);     // but lighter than the bed
  EXPECT_EQ(grey_at(image, 0.5 / 40), 0);  // the bed, past full scale: black
}

// `count` grains of 10 µm spread over the column, or (with `bed`) in its lowest 2 mm.
render::ParticleDiscs spread_grains(int count, bool bed) {
  render::ParticleDiscs p;
  std::uint32_t state = 12345;
  auto uniform = [&state] {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  };
  for (int i = 0; i < count; ++i) {
    p.x.push_back((uniform() - 0.5) * 0.063);
    p.y.push_back(bed ? 0.002 * uniform() : 0.457 * uniform());
    p.diameter.push_back(10e-6);
  }
  return p;
}

TEST(MassBands, ZoomWindowsHoldGrainsAtAnyCount) {
  using Where = render::ColumnInset::Where;
  double previous = 1;
  for (int count : {300, 3000, 30000}) {
    const auto p = spread_grains(count, false);
    for (auto where : {Where::top, Where::middle, Where::bottom}) {
      const auto w = render::zoom_window(p, 0.457, 0.0635, {where, 40});
      EXPECT_GE(w.grains, 15u) << count;
      EXPECT_LE(w.grains, 100u) << count;
    }
    const auto w = render::zoom_window(p, 0.457, 0.0635, {Where::middle, 40});
    EXPECT_LT(w.side, previous);  // more grains, a smaller window, a larger magnification
    previous = w.side;
  }
  // Everything settled: the bottom window sits on the bed and holds grains, the top one none.
  const auto bed = spread_grains(3000, true);
  const auto bottom = render::zoom_window(bed, 0.457, 0.0635, {Where::bottom, 40});
  EXPECT_LT(bottom.y0, 0.002);  // on the 2 mm bed
  EXPECT_GE(bottom.grains, 15u);
  EXPECT_LE(bottom.grains, 100u);
  EXPECT_EQ(render::zoom_window(bed, 0.457, 0.0635, {Where::top, 40}).grains, 0u);
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
