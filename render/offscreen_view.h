#pragma once

#include <filesystem>
#include <memory>

#include <vtkImageData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "render/gl_backend.h"

namespace sedem::render {

class EglContext;

// A render window of a fixed size that never shows on screen, on the backend that
// choose_backend() picks. Lives on one thread: VTK and GL are not shared across threads.
class OffscreenView {
 public:
  OffscreenView(int width, int height);
  ~OffscreenView();
  OffscreenView(const OffscreenView&) = delete;
  OffscreenView& operator=(const OffscreenView&) = delete;

  vtkRenderWindow* window() const { return window_; }
  // The first renderer, covering the whole window, white background.
  vtkRenderer* renderer() const { return renderer_; }
  GlBackend backend() const { return backend_; }

  // Renders and reads the colour buffer back (RGB).
  vtkSmartPointer<vtkImageData> capture();
  void save_png(const std::filesystem::path& file);

 private:
  GlBackend backend_;
  std::unique_ptr<EglContext> egl_;
  vtkSmartPointer<vtkRenderWindow> window_;
  vtkSmartPointer<vtkRenderer> renderer_;
};

// Writes an image as PNG; throws std::runtime_error if the file cannot be written.
void write_png(vtkImageData* image, const std::filesystem::path& file);
vtkSmartPointer<vtkImageData> read_png(const std::filesystem::path& file);

}  // namespace sedem::render
