#include "render/image_compare.h"

#include <vtkImageDifference.h>
#include <vtkSmartPointer.h>

#include "render/offscreen_view.h"

namespace sedem::render {

ImageComparison compare_with_baseline(vtkImageData* image, const std::filesystem::path& baseline,
                                      const std::filesystem::path& out_dir, double tolerance) {
  ImageComparison result;
  const std::string name = baseline.stem().string();
  if (!std::filesystem::exists(baseline)) {
    write_png(image, baseline);
    result.message = "no baseline existed; wrote the new image as " + baseline.string() +
                     " - look at it, and commit it if it is right";
    return result;
  }
  auto reference = read_png(baseline);
  int a[3], b[3];
  image->GetDimensions(a);
  reference->GetDimensions(b);
  auto new_file = out_dir / (name + ".png");
  if (a[0] != b[0] || a[1] != b[1]) {
    write_png(image, new_file);
    result.message = "size " + std::to_string(a[0]) + "x" + std::to_string(a[1]) +
                     " differs from the baseline's " + std::to_string(b[0]) + "x" +
                     std::to_string(b[1]) + "; new image: " + new_file.string();
    return result;
  }
  auto diff = vtkSmartPointer<vtkImageDifference>::New();
  diff->SetInputData(image);
  diff->SetImageData(reference);
  diff->Update();
  result.error = diff->GetThresholdedError();
  result.passed = result.error <= tolerance;
  if (!result.passed) {
    auto diff_file = out_dir / (name + ".diff.png");
    write_png(image, new_file);
    write_png(diff->GetOutput(), diff_file);
    result.message = "thresholded error " + std::to_string(result.error) + " > tolerance " +
                     std::to_string(tolerance) + " against " + baseline.string() +
                     "; new image: " + new_file.string() + ", difference: " + diff_file.string();
  }
  return result;
}

}  // namespace sedem::render
