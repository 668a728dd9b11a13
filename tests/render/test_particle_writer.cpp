#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include "render/particle_writer.h"
#include "render_test_support.h"

namespace sedem {
namespace {

TEST(ParticleWriter, VtpReadsBackWithEveryArray) {
  const auto dir = test::output_dir() / "writer";
  std::filesystem::remove_all(dir);
  const auto snap = test::lattice_snapshot();
  render::ParticleSeriesWriter writer(dir, 2500.0);
  writer.write(snap.time, snap.particles);

  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName((dir / "particles/particles_000000.vtp").c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  ASSERT_EQ(poly->GetNumberOfPoints(), 140);
  auto* pd = poly->GetPointData();
  for (const char* name : {"diameter", "radius", "velocity", "mass", "weight", "size_class", "id"})
    EXPECT_NE(pd->GetArray(name), nullptr) << name;
  ASSERT_NE(pd->GetVectors(), nullptr);
  EXPECT_STREQ(pd->GetVectors()->GetName(), "velocity");
  EXPECT_EQ(pd->GetVectors()->GetNumberOfComponents(), 3);
  EXPECT_DOUBLE_EQ(pd->GetArray("diameter")->GetTuple1(2), 60e-6);
  EXPECT_DOUBLE_EQ(pd->GetArray("radius")->GetTuple1(2), 30e-6);
  EXPECT_NEAR(pd->GetArray("mass")->GetTuple1(1), 2500 * 3.14159265358979 / 6 * 8e-15, 1e-25);
  EXPECT_DOUBLE_EQ(pd->GetVectors()->GetComponent(2, 1), -2e-3);
  double p[3];
  poly->GetPoint(8, p);
  EXPECT_DOUBLE_EQ(p[0], snap.particles.x[8]);
  EXPECT_DOUBLE_EQ(p[1], snap.particles.y[8]);
  auto* time = poly->GetFieldData()->GetArray("TimeValue");
  ASSERT_NE(time, nullptr);
  EXPECT_DOUBLE_EQ(time->GetTuple1(0), 42.0);
}

TEST(ParticleWriter, PvdListsEveryTimeInOrder) {
  const auto dir = test::output_dir() / "series";
  std::filesystem::remove_all(dir);
  render::ParticleSeriesWriter writer(dir, 2500.0);
  auto snap = test::lattice_snapshot();
  for (double t : {0.0, 10.0, 20.0}) {
    snap.time = t;
    writer.write(snap.time, snap.particles);
  }
  std::ifstream in(dir / "particles.pvd");
  std::stringstream text;
  text << in.rdbuf();
  const std::string pvd = text.str();
  EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos);
  auto a = pvd.find("timestep=\"0\" group=\"\" part=\"0\" file=\"particles/particles_000000.vtp\"");
  auto b =
      pvd.find("timestep=\"10\" group=\"\" part=\"0\" file=\"particles/particles_000001.vtp\"");
  auto c =
      pvd.find("timestep=\"20\" group=\"\" part=\"0\" file=\"particles/particles_000002.vtp\"");
  ASSERT_NE(a, std::string::npos) << pvd;
  ASSERT_NE(b, std::string::npos) << pvd;
  ASSERT_NE(c, std::string::npos) << pvd;
  EXPECT_LT(a, b);
  EXPECT_LT(b, c);
  EXPECT_FALSE(std::filesystem::exists(dir / "particles.pvd.tmp"));
}

}  // namespace
}  // namespace sedem
