#include <gtest/gtest.h>

#include <vtkImageData.h>

#include "render/column_animation.h"
#include "render/image_compare.h"
#include "render/offscreen_view.h"
#include "render_test_support.h"

namespace sedem {
namespace {

TEST(ColumnAnimation, NumberedFramesOnAFixedGreyScale) {
  const auto dir = test::output_dir() / "animation";
  std::filesystem::remove_all(dir);
  render::ColumnAnimation::Options options;
  options.label = "lattice";
  options.panel_width = 200;
  options.panel_height = 360;
  options.bands = 10;
  render::ColumnAnimation animation(dir, Cylinder{}, options);
  auto snap = test::lattice_snapshot();
  for (int frame = 0; frame < 3; ++frame) {
    snap.time = 100.0 * frame;
    for (auto& y : snap.particles.y) y *= 0.5;  // everything settles by half each frame
    animation.add(snap.time, snap.particles);
  }
  EXPECT_EQ(animation.frame_count(), 3);
  EXPECT_EQ(render::ColumnAnimation::frame_name(12), "frames/column_000012.png");
  for (int frame = 0; frame < 3; ++frame)
    ASSERT_TRUE(std::filesystem::exists(dir / render::ColumnAnimation::frame_name(frame)));
  EXPECT_FALSE(std::filesystem::exists(dir / render::ColumnAnimation::frame_name(3)));

  auto last = render::read_png(dir / render::ColumnAnimation::frame_name(2));
  int dims[3];
  last->GetDimensions(dims);
  EXPECT_EQ(dims[0], 200 + 110);
  EXPECT_EQ(dims[1], 360);
  auto result = render::compare_with_baseline(last, test::baseline("animation_frame.png"),
                                              test::output_dir());
  EXPECT_TRUE(result.passed) << result.message;
}

}  // namespace
}  // namespace sedem
