#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataReader.h>

#include <nlohmann/json.hpp>

#include "render/field_writer.h"
#include "render/hydrometer_writer.h"
#include "render/image_compare.h"
#include "render/offscreen_view.h"
#include "render/particle_writer.h"
#include "render_test_support.h"

namespace sedem {
namespace {

void expect_raw_compressed(const std::filesystem::path& file) {
  const auto text = test::read_text(file);
  EXPECT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos) << file;
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos) << file;
  EXPECT_NE(text.find("<DataArray type=\"Float64\" Name=\"TimeValue\""), std::string::npos);
}

void expect_series(const std::filesystem::path& pvd, const std::vector<double>& times) {
  const auto entries = test::parse_pvd(pvd);
  ASSERT_EQ(entries.size(), times.size()) << pvd;
  for (std::size_t i = 0; i < times.size(); ++i) {
    EXPECT_DOUBLE_EQ(entries[i].first, times[i]);
    EXPECT_TRUE(std::filesystem::exists(pvd.parent_path() / entries[i].second))
        << entries[i].second;
  }
  auto tmp = pvd;
  tmp += ".tmp";
  EXPECT_FALSE(std::filesystem::exists(tmp));
}

TEST(ParaviewFiles, ParticlesAreRawZlibWithTime) {
  const auto dir = test::output_dir() / "pv_particles";
  std::filesystem::remove_all(dir);
  render::ParticleSeriesWriter writer(dir, 2500.0);
  auto snap = test::lattice_snapshot();
  for (double t : {0.0, 0.5, 60.0}) {
    snap.time = t;
    writer.write(snap.time, snap.particles);
  }
  expect_series(dir / "particles.pvd", {0.0, 0.5, 60.0});
  expect_raw_compressed(dir / "particles/particles_000002.vtp");
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName((dir / "particles/particles_000002.vtp").c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 140);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfVerts(), 140);
  EXPECT_DOUBLE_EQ(reader->GetOutput()->GetFieldData()->GetArray("TimeValue")->GetTuple1(0), 60.0);
}

render::LayerFields layers(double time) {
  render::LayerFields f;
  f.time_s = time;
  f.column_height_m = 0.4;
  f.section_width_m = 0.06;
  for (int j = 0; j < 8; ++j) {  // j from the free surface down
    f.concentration_kg_m3.push_back(10.0 * j + time);
    f.suspension_density_kg_m3.push_back(1000.0 + 0.6 * (10.0 * j + time));
  }
  f.extra = {{"volume_fraction", std::vector<double>(8, 0.01)}};
  return f;
}

TEST(ParaviewFiles, FieldsAreAStripWithPointDataAlongDepth) {
  const auto dir = test::output_dir() / "pv_fields";
  std::filesystem::remove_all(dir);
  render::FieldSeriesWriter writer(dir);
  writer.write(layers(0.0));
  const auto file = writer.write(layers(30.0));
  expect_series(dir / "fields.pvd", {0.0, 30.0});
  EXPECT_EQ(file, dir / "fields/fields_000001.vtp");
  expect_raw_compressed(file);

  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* strip = reader->GetOutput();
  EXPECT_EQ(strip->GetNumberOfPoints(), 16);  // two per layer
  EXPECT_EQ(strip->GetNumberOfPolys(), 7);
  double bounds[6];
  strip->GetBounds(bounds);
  EXPECT_NEAR(bounds[0], -0.03, 1e-15);
  EXPECT_NEAR(bounds[1], 0.03, 1e-15);
  EXPECT_NEAR(bounds[2], 0.025, 1e-15);  // the lowest layer's centre
  EXPECT_NEAR(bounds[3], 0.375, 1e-15);  // the top layer's centre
  EXPECT_LT(bounds[5], 0.0);             // behind the particles
  auto* pd = strip->GetPointData();
  EXPECT_EQ(strip->GetCellData()->GetNumberOfArrays(), 0);
  ASSERT_NE(pd->GetScalars(), nullptr);
  EXPECT_STREQ(pd->GetScalars()->GetName(), "suspension_density");
  for (const char* name :
       {"suspension_density", "concentration", "solid_fraction", "depth", "bed", "volume_fraction"})
    ASSERT_NE(pd->GetArray(name), nullptr) << name;
  // Points 2j and 2j + 1 are layer j from the free surface, at its centre's height.
  EXPECT_DOUBLE_EQ(pd->GetArray("concentration")->GetTuple1(0), 30.0);
  EXPECT_DOUBLE_EQ(pd->GetArray("concentration")->GetTuple1(15), 100.0);
  EXPECT_NEAR(pd->GetArray("depth")->GetTuple1(1), 0.025, 1e-15);
  EXPECT_NEAR(strip->GetPoint(1)[1], 0.375, 1e-15);
  EXPECT_NEAR(pd->GetArray("depth")->GetTuple1(14), 0.375, 1e-15);
  EXPECT_DOUBLE_EQ(pd->GetArray("suspension_density")->GetTuple1(15), 1060.0);
  EXPECT_DOUBLE_EQ(pd->GetArray("solid_fraction")->GetTuple1(15), 100.0 / 2500.0);
  EXPECT_DOUBLE_EQ(strip->GetFieldData()->GetArray("TimeValue")->GetTuple1(0), 30.0);
}

TEST(ParaviewFiles, BedLayersAreClippedToAPackedBed) {
  // The demo's bed at 120 s: 27 196 kg/m^3 of grains, a suspension of 17 317 kg/m^3.
  auto f = layers(0.0);
  f.concentration_kg_m3.back() = 27196;
  f.suspension_density_kg_m3.back() = 17317;
  auto strip = render::layer_strip(f);
  auto* pd = strip->GetPointData();
  const vtkIdType bed = 14, above = 12;
  EXPECT_DOUBLE_EQ(pd->GetArray("solid_fraction")->GetTuple1(bed), render::kBedSolidFraction);
  EXPECT_DOUBLE_EQ(pd->GetArray("concentration")->GetTuple1(bed), 0.64 * 2500);
  EXPECT_DOUBLE_EQ(pd->GetArray("suspension_density")->GetTuple1(bed), 1000 + 0.64 * 1500);
  EXPECT_EQ(pd->GetArray("bed")->GetTuple1(bed), 1);
  EXPECT_EQ(pd->GetArray("bed")->GetTuple1(above), 0);
  EXPECT_DOUBLE_EQ(pd->GetArray("concentration")->GetTuple1(above), 60.0);
  double range[2];
  pd->GetArray("suspension_density")->GetRange(range);
  EXPECT_LE(range[1], 2500.0);  // never denser than the grains themselves
}

TEST(ParaviewFiles, FieldsRejectMismatchedLayers) {
  auto f = layers(0.0);
  f.concentration_kg_m3.pop_back();
  EXPECT_THROW(render::layer_strip(f), std::invalid_argument);
}

// Volume enclosed by a triangulated surface (divergence theorem): positive when the
// triangles face outwards.
double signed_volume(vtkPolyData* surface) {
  auto tri = vtkSmartPointer<vtkTriangleFilter>::New();
  tri->SetInputData(surface);
  tri->Update();
  vtkPolyData* t = tri->GetOutput();
  double volume = 0;
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < t->GetNumberOfCells(); ++c) {
    t->GetCellPoints(c, ids);
    std::array<std::array<double, 3>, 3> p;
    for (int k = 0; k < 3; ++k) t->GetPoint(ids->GetId(k), p[std::size_t(k)].data());
    const auto& [a, b, d] = p;
    volume += (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
               a[2] * (b[0] * d[1] - b[1] * d[0])) /
              6.0;
  }
  return volume;
}

TEST(ParaviewFiles, BulbSurfaceEnclosesTheProfileVolume) {
  // A cone of height 2 cm on a cylinder of 8 cm, radius 1 cm, closed at the top.
  const render::BulbProfile profile{{0.0, 0.02, 0.10}, {0.0, 0.01, 0.01}};
  const int n = 48;
  auto surface = render::bulb_surface(profile, 0.25, n);
  const double polygon_area = 0.5 * n * 0.01 * 0.01 * std::sin(2 * std::numbers::pi / n);
  EXPECT_NEAR(signed_volume(surface), polygon_area * (0.08 + 0.02 / 3.0), 1e-12);
  double bounds[6];
  surface->GetBounds(bounds);
  EXPECT_DOUBLE_EQ(bounds[2], 0.25);  // tip
  EXPECT_NEAR(bounds[3], 0.35, 1e-15);
  EXPECT_NEAR(bounds[1], 0.01, 1e-15);
  // The back half encloses half of it, lies behind the section's plane and carries the
  // outline in that plane.
  auto half = render::bulb_surface(profile, 0.25, n, render::BulbPart::back_half);
  EXPECT_NEAR(signed_volume(half), 0.5 * polygon_area * (0.08 + 0.02 / 3.0), 1e-12);
  half->GetBounds(bounds);
  EXPECT_NEAR(bounds[5], 0.0, 1e-15);
  EXPECT_NEAR(bounds[4], -0.01, 1e-15);
  EXPECT_EQ(half->GetNumberOfLines(), 1);
}

TEST(ParaviewFiles, HydrometerSeriesPlacesTheTipAtItsDepth) {
  const auto dir = test::output_dir() / "pv_hydrometer";
  std::filesystem::remove_all(dir);
  render::HydrometerSeriesWriter writer(dir, {{0.0, 0.02, 0.14, 0.30}, {0.0, 0.014, 0.014, 0.003}},
                                        0.457);
  writer.write(120.0, 0.20);
  const auto file = writer.write(300.0, 0.21);
  expect_series(dir / "hydrometer.pvd", {120.0, 300.0});
  expect_raw_compressed(file);
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  EXPECT_GT(poly->GetNumberOfPolys(), 0);
  double bounds[6];
  poly->GetBounds(bounds);
  EXPECT_LE(bounds[5], 0.0);  // nothing in front of the particles' plane z = 0
  EXPECT_NEAR(bounds[2], 0.457 - 0.21, 1e-12);
  EXPECT_NEAR(bounds[3], 0.457 - 0.21 + 0.30, 1e-12);
  EXPECT_DOUBLE_EQ(poly->GetFieldData()->GetArray("tip_depth")->GetTuple1(0), 0.21);
  EXPECT_DOUBLE_EQ(poly->GetFieldData()->GetArray("TimeValue")->GetTuple1(0), 300.0);
}

std::string run(const std::string& command) {
  std::string out;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    std::array<char, 4096> buffer;
    while (std::fgets(buffer.data(), int(buffer.size()), pipe)) out += buffer.data();
    ::pclose(pipe);
  }
  return out;
}

const std::filesystem::path kSource = SEDEM_SOURCE_DIR;

// ParaView's own pvpython (unpacked by scripts/setup.sh) on `script` with `args`.
std::string pvpython(const std::filesystem::path& script, const std::string& args) {
  return run("'" + (kSource / "tests/render/pvpython.sh").string() + "' '" + script.string() +
             "' " + args + " 2>&1");
}

// A small run folder written by sedem's own writers: 140 particles at 0, 10 and 20 s, the
// layer fields at the same times (the bottom layers overfilled, as a bed is), and the
// hydrometer at 10 and 20 s.
std::filesystem::path write_run(const std::string& name) {
  const auto dir = test::output_dir() / name;
  std::filesystem::remove_all(dir);
  render::ParticleSeriesWriter particles(dir, 2500.0);
  render::FieldSeriesWriter fields(dir);
  render::HydrometerSeriesWriter bulb(dir, {{0.0, 0.02, 0.14, 0.30}, {0.0, 0.014, 0.014, 0.003}},
                                      0.457);
  auto snap = test::lattice_snapshot();
  for (double t : {0.0, 10.0, 20.0}) {
    snap.time = t;
    particles.write(snap.time, snap.particles);
    render::LayerFields f;
    f.time_s = t;
    for (int j = 0; j < 40; ++j) {
      const double c = j < 36 ? 20.0 + j + t : 30000.0;  // kg/m^3
      f.concentration_kg_m3.push_back(c);
      f.suspension_density_kg_m3.push_back(1000 + 0.6 * c);
    }
    fields.write(f);
    if (t > 0) bulb.write(t, 0.15 + 0.001 * t);
  }
  return dir;
}

TEST(ParaviewFiles, ParaviewReadsEverySeriesAndShowsItWithNoFurtherStep) {
  const auto dir = write_run("pv_paraview");
  const auto out = pvpython(kSource / "tests/render/check_run_pvd.py", "'" + dir.string() + "'");
  const auto at = out.find("REPORT {");
  ASSERT_NE(at, std::string::npos) << "pvpython gave no report (run scripts/setup.sh):\n" << out;
  const auto report = nlohmann::json::parse(out.substr(at + 7, out.find('\n', at) - at - 7));

  const auto& p = report.at("particles");
  EXPECT_EQ(p.at("times"), nlohmann::json::parse("[0.0, 10.0, 20.0]"));
  EXPECT_EQ(p.at("class"), "vtkPolyData");
  EXPECT_EQ(p.at("points"), 140);
  EXPECT_EQ(p.at("cells"), 140);  // one vertex each: ParaView draws them as they are
  const auto& pd = p.at("point_data");
  for (const char* name : {"diameter", "radius", "velocity", "mass", "weight"})
    EXPECT_EQ(pd.at(name).at("type"), "double") << name;
  EXPECT_EQ(pd.at("size_class").at("type"), "int");
  EXPECT_EQ(pd.at("id").at("type"), "unsigned int");
  EXPECT_EQ(pd.at("velocity").at("components"), 3);
  EXPECT_DOUBLE_EQ(pd.at("diameter").at("range")[0].get<double>(), 5e-6);
  EXPECT_DOUBLE_EQ(pd.at("diameter").at("range")[1].get<double>(), 60e-6);
  EXPECT_DOUBLE_EQ(pd.at("radius").at("range")[1].get<double>(), 30e-6);
  EXPECT_DOUBLE_EQ(pd.at("id").at("range")[1].get<double>(), 139);
  EXPECT_DOUBLE_EQ(p.at("field_data").at("TimeValue").at("range")[0].get<double>(), 20.0);
  EXPECT_EQ(p.at("representation"), "Surface");
  EXPECT_EQ(p.at("colour"), nlohmann::json::parse(R"(["POINTS", "diameter"])"));

  // The fields draw as a coloured strip by default: point data, coloured by density.
  const auto& f = report.at("fields");
  EXPECT_EQ(f.at("times"), nlohmann::json::parse("[0.0, 10.0, 20.0]"));
  EXPECT_EQ(f.at("class"), "vtkPolyData");
  EXPECT_EQ(f.at("points"), 80);
  EXPECT_EQ(f.at("cell_data").size(), 0u);
  EXPECT_EQ(f.at("representation"), "Surface");
  EXPECT_EQ(f.at("colour"), nlohmann::json::parse(R"(["POINTS", "suspension_density"])"));
  const auto& fd = f.at("point_data");
  for (const char* name : {"suspension_density", "concentration", "solid_fraction", "depth"})
    EXPECT_EQ(fd.at(name).at("type"), "double") << name;
  EXPECT_EQ(fd.at("bed").at("type"), "unsigned char");
  // Physical at the bed: a packed bed, never denser than the grains.
  EXPECT_DOUBLE_EQ(fd.at("suspension_density").at("range")[0].get<double>(), 1000 + 0.6 * 40);
  EXPECT_DOUBLE_EQ(fd.at("suspension_density").at("range")[1].get<double>(), 1000 + 0.64 * 1500);
  EXPECT_DOUBLE_EQ(fd.at("concentration").at("range")[1].get<double>(), 0.64 * 2500);
  EXPECT_DOUBLE_EQ(fd.at("solid_fraction").at("range")[1].get<double>(), 0.64);
  EXPECT_NEAR(fd.at("depth").at("range")[1].get<double>(), 0.457 * 79 / 80, 1e-12);

  const auto& h = report.at("hydrometer");
  EXPECT_EQ(h.at("times"), nlohmann::json::parse("[10.0, 20.0]"));
  EXPECT_DOUBLE_EQ(h.at("field_data").at("tip_depth").at("range")[0].get<double>(), 0.17);
  EXPECT_EQ(h.at("representation"), "Surface");
}

// A run of 30 000 grains as sample 5 holds them (2.5-70 um, as many of each size, H = 0.457 m,
// B = 0.0635 m), written by sedem's own writers at 0 and 300 s: each grain has fallen at its
// Stokes velocity from where it started (a fixed pseudo-random lattice) and the ones that
// reached the bottom lie in a bed; the layers' suspension density follows from the grains
// (1000-1025 kg/m^3 over the suspension, thinning upwards), the bed's layers overfilled.
std::filesystem::path write_sample5_like_run(const std::string& name) {
  const auto dir = test::output_dir() / name;
  std::filesystem::remove_all(dir);
  const double height = 0.457, width = 0.0635, rho_p = 2500, rho_f = 1000;
  const std::size_t n = 30000, layers = 400;
  render::ParticleSeriesWriter particles(dir, rho_p);
  render::FieldSeriesWriter fields(dir);
  render::HydrometerSeriesWriter bulb(dir, {{0.0, 0.02, 0.14, 0.30}, {0.0, 0.014, 0.014, 0.003}},
                                      height);
  Snapshot snap;
  snap.particles.resize(n);
  auto& p = snap.particles;
  std::uint32_t state = 12345;
  auto uniform = [&state] {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  };
  std::vector<double> x0(n), y0(n);
  for (std::size_t i = 0; i < n; ++i) {
    x0[i] = (uniform() - 0.5) * (width - 1e-4);
    y0[i] = 0.012 + uniform() * (height - 0.014);
    p.diameter[i] = 2.5e-6 * std::pow(70.0 / 2.5, double(i % 220) / 219.0);
    p.weight[i] = 1.0;
    p.size_class[i] = std::int32_t(i % 220);
    p.id[i] = std::uint32_t(i);
  }
  for (double t : {0.0, 300.0}) {
    snap.time = t;
    std::vector<double> solid(layers, 0.0);  // kg/m^3 of grains, top layer first
    std::size_t settled = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double v = (rho_p - rho_f) * 9.81 * p.diameter[i] * p.diameter[i] / 18e-3;
      p.x[i] = x0[i];
      p.y[i] = y0[i] - v * t;
      p.vy[i] = -v;
      if (p.y[i] < 0.012) {  // in the bed: packed into the bottom 12 mm
        p.y[i] = 0.0005 + 0.0115 * double(settled++ % 997) / 997.0;
        p.vy[i] = 0;
      }
      const auto j = std::min(layers - 1, std::size_t((height - p.y[i]) / height * layers));
      // 60 g in the paper's litre, shared by the grains: 0.06 kg/m^3 each on average.
      solid[j] += (p.y[i] < 0.012 ? 20.0 : 1.0) * 60.0 * double(layers) / double(n);
    }
    particles.write(snap.time, snap.particles);
    render::LayerFields f;
    f.time_s = t;
    f.column_height_m = height;
    f.section_width_m = width;
    for (std::size_t j = 0; j < layers; ++j) {
      f.concentration_kg_m3.push_back(solid[j]);
      f.suspension_density_kg_m3.push_back(rho_f + (1 - rho_f / rho_p) * solid[j]);
    }
    fields.write(f);
    if (t > 0) bulb.write(t, 0.17);
  }
  return dir;
}

// Pixels of [x0, x1) x [y0, y1) of a clear hue (not white, grey or black): the discs, not text.
int coloured_pixels(vtkImageData* image, int x0, int x1, int y0, int y1) {
  int n = 0;
  for (int j = y0; j < y1; ++j)
    for (int i = x0; i < x1; ++i) {
      const auto* px = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
      n += std::max({px[0], px[1], px[2]}) - std::min({px[0], px[1], px[2]}) > 40;
    }
  return n;
}

// The numbers the macro printed on its line "sedem_paraview: WHAT ...".
std::vector<double> macro_line(const std::string& out, const std::string& what) {
  std::vector<double> numbers;
  const auto at = out.find("sedem_paraview: " + what + " ");
  if (at == std::string::npos) return numbers;
  std::istringstream line(out.substr(at, out.find('\n', at) - at));
  std::string word;
  while (line >> word) {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (end != word.c_str() && *end == '\0') numbers.push_back(v);
  }
  return numbers;
}

// Distinct colours (to 8 levels a channel) among the pixels of [x0, x1) x [y0, y1), rows from
// the bottom, leaving out white and near-white.
int distinct_colours(vtkImageData* image, int x0, int x1, int y0, int y1) {
  std::set<int> colours;
  for (int j = y0; j < y1; ++j)
    for (int i = x0; i < x1; ++i) {
      const auto* px = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
      if (px[0] > 245 && px[1] > 245 && px[2] > 245) continue;
      colours.insert((px[0] / 8) * 1024 + (px[1] / 8) * 32 + px[2] / 8);
    }
  return int(colours.size());
}

TEST(ParaviewFiles, TheStateMacroShowsARunAsThePaperDoes) {
  const auto dir = write_sample5_like_run("pv_state");
  const auto png = dir / "state.png";
  const auto out = pvpython(kSource / "docs/sedem_paraview.py",
                            "'" + dir.string() + "' --time 300 --screenshot '" + png.string() +
                                "' --state '" + (dir / "sedem.pvsm").string() + "'");
  ASSERT_TRUE(std::filesystem::exists(png)) << out;
  EXPECT_TRUE(std::filesystem::exists(dir / "sedem.pvsm")) << out;
  const auto image = render::read_png(png);
  int dims[3];
  image->GetDimensions(dims);
  ASSERT_EQ(dims[0], 1600);
  ASSERT_EQ(dims[1], 900);
  // The layout: the column in x < 480, the zoom in [480, 960), the chart in [960, 1600). The
  // column's strip is 0.0635 m of 1.04 * 0.457 m over 900 px: 120 px wide about x = 240.
  const int strip0 = 190, strip1 = 290;
  // The suspension is coloured over its own range: its upper half (y from 0.5 H to 0.9 H)
  // holds many shades of blue, not white; the lower half is darker than the upper.
  EXPECT_GT(distinct_colours(image, strip0, strip1, 480, 800), 20);
  EXPECT_LT(test::pixels_of(image, {255, 255, 255}, strip0, strip1), (strip1 - strip0) * 300);
  // Grains by size: the bed's grains in the column take many colours of the diameter map.
  EXPECT_GT(distinct_colours(image, strip0, strip1, 10, 40), 15);
  // The bulb: its outline in the column's upper part, darker than the strip behind it.
  EXPECT_GT(test::dark_pixels(image, strip0, strip1, 560, 900), 100);
  // The chart's y labels whole: nothing dark touches the chart's left edge (a clipped label
  // does), and there are labels in the 100 px beside it.
  EXPECT_EQ(test::dark_pixels(image, 960, 964, 0, 900), 0);
  EXPECT_GT(test::dark_pixels(image, 964, 1060, 40, 860), 300);
  // The zoom: discs of many diameters (many colours of the map), each several pixels across.
  EXPECT_GT(distinct_colours(image, 490, 950, 20, 780), 20);
  EXPECT_GT(coloured_pixels(image, 490, 950, 20, 780), 3000);
  // The strip's range is the suspension's (about 1005-1036 kg/m^3 here, the bed apart), not
  // a sliver of it: the macro prints what it chose.
  const auto strip = macro_line(out, "strip");
  ASSERT_EQ(strip.size(), 3u) << out;
  EXPECT_LT(strip[0], 1010.0) << out;
  EXPECT_GT(strip[1], 1025.0) << out;
  EXPECT_NEAR(strip[2], 0.0125, 0.002) << out;  // the bed's surface, m
  // The zoom sits on the bed's surface, its median grain at least 8 px across.
  const auto zoom = macro_line(out, "zoom");
  ASSERT_EQ(zoom.size(), 6u) << out;
  EXPECT_NEAR(zoom[1], 0.0125, 0.003) << out;
  EXPECT_GE(zoom[4] * 900 / (2 * zoom[2]), 7.9) << out;
  auto result = render::compare_with_baseline(image, test::baseline("paraview_state.png"),
                                              test::output_dir(), 20.0);
  EXPECT_TRUE(result.passed) << result.message;
}

const std::filesystem::path kSedem = SEDEM_EXE;

TEST(ParaviewCommand, WithoutPvpythonItStopsAndSaysSo) {
  const auto dir = write_run("pv_command_none");
  const auto out = run("env -u SEDEM_PVPYTHON PATH=/nonexistent '" + kSedem.string() +
                       "' paraview '" + dir.string() + "' 2>&1; echo \"status=$?\"");
  EXPECT_NE(out.find("status=1"), std::string::npos) << out;
  EXPECT_NE(out.find("no pvpython on PATH"), std::string::npos) << out;
  EXPECT_NE(out.find("--pvpython"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(dir / "sedem.pvsm"));
  const auto named = run("'" + kSedem.string() + "' paraview '" + dir.string() +
                         "' --pvpython /nonexistent/pvpython 2>&1; echo \"status=$?\"");
  EXPECT_NE(named.find("status=1"), std::string::npos) << named;
  EXPECT_NE(named.find("/nonexistent/pvpython cannot be run"), std::string::npos) << named;
  // A folder that is not a run is refused before pvpython is looked for.
  const auto empty = test::output_dir() / "pv_command_empty";
  std::filesystem::create_directories(empty);
  const auto refused =
      run("'" + kSedem.string() + "' paraview '" + empty.string() + "' 2>&1; echo \"status=$?\"");
  EXPECT_NE(refused.find("no particles.pvd or fields.pvd"), std::string::npos) << refused;
}

TEST(ParaviewCommand, WritesAStateThatLoadsBackAsTheSamePicture) {
  const auto dir = write_run("pv_command");
  const auto shot = dir / "command.png";
  const auto out = run("'" + kSedem.string() + "' paraview '" + dir.string() + "' --pvpython '" +
                       (kSource / "tests/render/pvpython.sh").string() + "' --screenshot '" +
                       shot.string() + "' 2>&1; echo \"status=$?\"");
  ASSERT_NE(out.find("status=0"), std::string::npos) << out;
  EXPECT_NE(out.find("sedem.pvsm"), std::string::npos) << out;
  ASSERT_TRUE(std::filesystem::exists(dir / "sedem.pvsm")) << out;
  EXPECT_FALSE(std::filesystem::exists(dir / "sedem_paraview.py.tmp"));
  ASSERT_TRUE(std::filesystem::exists(shot)) << out;
  // ParaView loads the state back (File > Load State) and draws the same three views.
  const auto loaded = dir / "loaded.png";
  const auto back = pvpython(kSource / "tests/render/load_state.py",
                             "'" + (dir / "sedem.pvsm").string() + "' '" + loaded.string() + "'");
  EXPECT_NE(back.find("LOADED 3 views"), std::string::npos) << back;
  ASSERT_TRUE(std::filesystem::exists(loaded)) << back;
  auto result =
      render::compare_with_baseline(render::read_png(loaded), shot, test::output_dir(), 5.0);
  EXPECT_TRUE(result.passed) << result.message;
}

}  // namespace
}  // namespace sedem
