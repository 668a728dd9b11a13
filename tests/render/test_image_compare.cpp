// The image-baseline helper itself: what it does when an image differs or a baseline is
// missing. Its input is a small plot, so these tests do not depend on any figure's look.
#include <gtest/gtest.h>

#include "render/image_compare.h"
#include "render/offscreen_view.h"
#include "render/plot.h"
#include "render_test_support.h"

namespace sedem {
namespace {

vtkSmartPointer<vtkImageData> line_image(double slope) {
  render::Plot p;
  p.title = "line";
  p.x = render::axis("x", "m", 0.0, 1.0);
  p.y = render::axis("y", "m", 0.0, 1.0);
  p.series = {render::PlotSeries("y", {0.0, 1.0}, {0.0, slope})};
  return render::render_figure(render::single_plot(p, 240, 180));
}

TEST(ImageCompare, ADifferentImageFailsAndLeavesNewAndDiffFiles) {
  const auto dir = test::output_dir() / "compare_fail";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto baseline = dir / "line.png";
  render::write_png(line_image(1.0), baseline);
  auto same = render::compare_with_baseline(line_image(1.0), baseline, dir);
  EXPECT_TRUE(same.passed) << same.message;
  auto result = render::compare_with_baseline(line_image(0.2), baseline, dir / "new");
  EXPECT_FALSE(result.passed);
  EXPECT_TRUE(std::filesystem::exists(dir / "new" / "line.png")) << result.message;
  EXPECT_TRUE(std::filesystem::exists(dir / "new" / "line.diff.png")) << result.message;
}

TEST(ImageCompare, AMissingBaselineIsWrittenAndFails) {
  const auto dir = test::output_dir() / "compare_missing";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto missing = dir / "no_such_baseline.png";
  auto result = render::compare_with_baseline(line_image(1.0), missing, dir);
  EXPECT_FALSE(result.passed);
  EXPECT_TRUE(std::filesystem::exists(missing));
  // Once written, the same image passes against it.
  auto again = render::compare_with_baseline(line_image(1.0), missing, dir);
  EXPECT_TRUE(again.passed) << again.message;
}

}  // namespace
}  // namespace sedem
