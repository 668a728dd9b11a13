#include <gtest/gtest.h>

#include "render/column_view.h"
#include "render/image_compare.h"
#include "render/offscreen_view.h"
#include "render_test_support.h"

namespace sedem {
namespace {

TEST(ColumnRender, MatchesBaseline) {
  const auto out = test::output_dir() / "column_lattice.png";
  render::render_column_png(test::lattice_snapshot(), Cylinder{}, "lattice", 240, 800, out);
  auto image = render::read_png(out);
  auto result = render::compare_with_baseline(image, test::baseline("column_lattice.png"),
                                              test::output_dir());
  EXPECT_TRUE(result.passed) << result.message;
}

TEST(ImageCompare, ADifferentImageFailsAndLeavesNewAndDiffFiles) {
  const auto dir = test::output_dir() / "compare_fail";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  auto snap = test::lattice_snapshot();
  for (auto& y : snap.particles.y) y = 0.5 * y;  // everything moved down
  render::render_column_png(snap, Cylinder{}, "lattice", 240, 800, dir / "moved.png");
  auto result = render::compare_with_baseline(render::read_png(dir / "moved.png"),
                                              test::baseline("column_lattice.png"), dir);
  EXPECT_FALSE(result.passed);
  EXPECT_TRUE(std::filesystem::exists(dir / "column_lattice.png")) << result.message;
  EXPECT_TRUE(std::filesystem::exists(dir / "column_lattice.diff.png")) << result.message;
}

TEST(ImageCompare, AMissingBaselineIsWrittenAndFails) {
  const auto dir = test::output_dir() / "compare_missing";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  render::render_column_png(test::lattice_snapshot(), Cylinder{}, "lattice", 240, 800,
                            dir / "img.png");
  const auto missing = dir / "no_such_baseline.png";
  auto result = render::compare_with_baseline(render::read_png(dir / "img.png"), missing, dir);
  EXPECT_FALSE(result.passed);
  EXPECT_TRUE(std::filesystem::exists(missing));
  // Once written, the same image passes against it.
  auto again = render::compare_with_baseline(render::read_png(dir / "img.png"), missing, dir);
  EXPECT_TRUE(again.passed) << again.message;
}

}  // namespace
}  // namespace sedem
