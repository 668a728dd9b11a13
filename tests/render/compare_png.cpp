// A picture made outside sedem (a browser's screenshot) against its baseline, the way the
// render tests compare theirs (render/image_compare.h), for the tests that are scripts:
//
//   sedem_compare_png IMAGE BASELINE OUT_DIR [ROWS [TOLERANCE]]
//
// compares the top ROWS rows of IMAGE (all of it when ROWS is 0 or absent). Exit status 0 when
// it matches, 1 with the reason (and the new image and the difference in OUT_DIR) when not, 2 on
// a bad command line or an unreadable image.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include "render/image_compare.h"
#include "render/offscreen_view.h"

namespace {

// The top `rows` rows of an RGB(A) image, as RGB (VTK's rows run from the bottom).
vtkSmartPointer<vtkImageData> top_rows(vtkImageData* image, int rows) {
  int dims[3];
  image->GetDimensions(dims);
  if (rows <= 0 || rows > dims[1]) rows = dims[1];
  const int channels = image->GetNumberOfScalarComponents();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(dims[0], rows, 1);
  out->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < dims[0]; ++i) {
      const auto* from =
          static_cast<unsigned char*>(image->GetScalarPointer(i, dims[1] - rows + j, 0));
      auto* to = static_cast<unsigned char*>(out->GetScalarPointer(i, j, 0));
      for (int c = 0; c < 3; ++c) to[c] = from[channels >= 3 ? c : 0];
    }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4 || argc > 6) {
    std::fprintf(stderr, "usage: %s IMAGE BASELINE OUT_DIR [ROWS [TOLERANCE]]\n", argv[0]);
    return 2;
  }
  try {
    const int rows = argc > 4 ? std::atoi(argv[4]) : 0;
    const double tolerance = argc > 5 ? std::atof(argv[5]) : 10.0;
    auto image = sedem::render::read_png(argv[1]);
    const auto result =
        sedem::render::compare_with_baseline(top_rows(image, rows), argv[2], argv[3], tolerance);
    std::printf("%s (thresholded error %g, tolerance %g)\n",
                result.passed ? "matches the baseline" : result.message.c_str(), result.error,
                tolerance);
    return result.passed ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    return 2;
  }
}
