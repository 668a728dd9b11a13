#include <gtest/gtest.h>

#include <cstdlib>

#include <vtkImageData.h>

#include "render/gl_backend.h"
#include "render/offscreen_view.h"

namespace sedem {
namespace {

TEST(Backend, EnvironmentChoosesIt) {
  ::setenv("SEDEM_GL", "x", 1);
  EXPECT_EQ(render::choose_backend(), render::GlBackend::x);
  ::setenv("SEDEM_GL", "egl", 1);
  EXPECT_EQ(render::choose_backend(), render::GlBackend::egl);
  ::setenv("SEDEM_GL", "vulkan", 1);
  EXPECT_THROW(render::choose_backend(), std::runtime_error);
  ::setenv("SEDEM_GL", "egl", 1);
}

TEST(Backend, EglDrawsTheBackgroundWithNoDisplay) {
  ::setenv("SEDEM_GL", "egl", 1);
  render::OffscreenView view(64, 48);
  view.renderer()->SetBackground(1.0, 0.0, 0.0);
  auto image = view.capture();
  int dims[3];
  image->GetDimensions(dims);
  ASSERT_EQ(dims[0], 64);
  ASSERT_EQ(dims[1], 48);
  auto* px = static_cast<unsigned char*>(image->GetScalarPointer(10, 10, 0));
  EXPECT_EQ(px[0], 255);
  EXPECT_EQ(px[1], 0);
  EXPECT_EQ(px[2], 0);
}

}  // namespace
}  // namespace sedem
