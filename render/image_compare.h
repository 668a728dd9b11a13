#pragma once

#include <filesystem>
#include <string>

#include <vtkImageData.h>

namespace sedem::render {

struct ImageComparison {
  bool passed = false;
  double error = 0;     // vtkImageDifference's thresholded error
  std::string message;  // what failed and which files to look at
};

// Compares `image` with the PNG at `baseline` (vtkImageDifference, thresholded error, must
// not exceed `tolerance`). On failure writes `<name>.png` (the new image) and
// `<name>.diff.png` into `out_dir` and names them in the message. A missing baseline is
// written at `baseline` and the comparison fails: a test never passes without one.
ImageComparison compare_with_baseline(vtkImageData* image, const std::filesystem::path& baseline,
                                      const std::filesystem::path& out_dir,
                                      double tolerance = 10.0);

}  // namespace sedem::render
