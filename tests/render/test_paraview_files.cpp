#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include "render/field_writer.h"
#include "render/hydrometer_writer.h"
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
    writer.write(snap);
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

TEST(ParaviewFiles, FieldsAreLayerImagesWithTheSurfaceOnTop) {
  const auto dir = test::output_dir() / "pv_fields";
  std::filesystem::remove_all(dir);
  render::FieldSeriesWriter writer(dir);
  writer.write(layers(0.0));
  const auto file = writer.write(layers(30.0));
  expect_series(dir / "fields.pvd", {0.0, 30.0});
  EXPECT_EQ(file, dir / "fields/fields_000001.vti");
  expect_raw_compressed(file);

  auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 2);
  EXPECT_EQ(dims[1], 9);
  EXPECT_EQ(dims[2], 1);
  EXPECT_EQ(image->GetNumberOfCells(), 8);
  double bounds[6];
  image->GetBounds(bounds);
  EXPECT_NEAR(bounds[0], -0.03, 1e-15);
  EXPECT_NEAR(bounds[1], 0.03, 1e-15);
  EXPECT_NEAR(bounds[3], 0.4, 1e-15);
  auto* cd = image->GetCellData();
  for (const char* name : {"suspension_density", "concentration", "depth", "volume_fraction"})
    ASSERT_NE(cd->GetArray(name), nullptr) << name;
  // The top cell (highest y) is the first layer below the free surface.
  EXPECT_DOUBLE_EQ(cd->GetArray("concentration")->GetTuple1(7), 30.0);
  EXPECT_DOUBLE_EQ(cd->GetArray("concentration")->GetTuple1(0), 100.0);
  EXPECT_NEAR(cd->GetArray("depth")->GetTuple1(7), 0.025, 1e-15);
  EXPECT_NEAR(cd->GetArray("depth")->GetTuple1(0), 0.375, 1e-15);
  EXPECT_DOUBLE_EQ(cd->GetArray("suspension_density")->GetTuple1(0), 1060.0);
  EXPECT_DOUBLE_EQ(image->GetFieldData()->GetArray("TimeValue")->GetTuple1(0), 30.0);
}

TEST(ParaviewFiles, FieldsRejectMismatchedLayers) {
  auto f = layers(0.0);
  f.concentration_kg_m3.pop_back();
  EXPECT_THROW(render::layer_image(f), std::invalid_argument);
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
  EXPECT_NEAR(bounds[2], 0.457 - 0.21, 1e-12);
  EXPECT_NEAR(bounds[3], 0.457 - 0.21 + 0.30, 1e-12);
  EXPECT_DOUBLE_EQ(poly->GetFieldData()->GetArray("tip_depth")->GetTuple1(0), 0.21);
  EXPECT_DOUBLE_EQ(poly->GetFieldData()->GetArray("TimeValue")->GetTuple1(0), 300.0);
}

std::string run(const std::string& command) {
  std::string out;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    std::array<char, 512> buffer;
    while (std::fgets(buffer.data(), int(buffer.size()), pipe)) out += buffer.data();
    ::pclose(pipe);
  }
  return out;
}

TEST(ParaviewFiles, ParaviewOpensTheParticleSeries) {
  if (std::system("command -v pvpython > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "pvpython is not on PATH (ParaView is not installed): the series is not "
                    "checked through ParaView here";
  const auto dir = test::output_dir() / "pv_paraview";
  std::filesystem::remove_all(dir);
  render::ParticleSeriesWriter writer(dir, 2500.0);
  auto snap = test::lattice_snapshot();
  for (double t : {0.0, 10.0, 20.0}) {
    snap.time = t;
    writer.write(snap);
  }
  const auto script =
      std::filesystem::path(SEDEM_SOURCE_DIR) / "tests" / "render" / "check_particles_pvd.py";
  const auto out = run("pvpython --force-offscreen-rendering '" + script.string() + "' '" +
                       (dir / "particles.pvd").string() + "' 2>&1");
  EXPECT_NE(out.find("times 0.0 10.0 20.0"), std::string::npos) << out;
  EXPECT_NE(out.find("arrays diameter id mass radius size_class velocity weight"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("points 140"), std::string::npos) << out;
}

}  // namespace
}  // namespace sedem
