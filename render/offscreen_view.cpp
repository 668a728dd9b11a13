#include "render/offscreen_view.h"

#include <stdexcept>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include "render/atomic_write.h"
#include "render/egl_context.h"

namespace sedem::render {

OffscreenView::OffscreenView(int width, int height) : backend_(choose_backend()) {
  if (backend_ == GlBackend::egl) {
    egl_ = std::make_unique<EglContext>();
    auto generic = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
    // The context is ours and already current; VTK only draws into its framebuffers.
    generic->SetOffScreenRendering(1);
    generic->SetIsCurrent(true);
    generic->SetReadyForRendering(true);
    generic->SetFrameBlitModeToNoBlit();
    window_ = generic;
  } else {
    window_ = vtkSmartPointer<vtkRenderWindow>::New();
    window_->SetOffScreenRendering(1);
  }
  window_->SetSize(width, height);
  window_->SetMultiSamples(0);  // identical pixels run to run, for baseline images
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  renderer_->SetBackground(1, 1, 1);
  window_->AddRenderer(renderer_);
}

OffscreenView::~OffscreenView() {
  // GL resources must go while their context is still current.
  if (egl_) egl_->make_current();
  window_->Finalize();
  renderer_ = nullptr;
  window_ = nullptr;
}

vtkSmartPointer<vtkImageData> OffscreenView::capture() {
  if (egl_) egl_->make_current();
  window_->Render();
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window_);
  grab->SetInputBufferTypeToRGB();
  grab->SetReadFrontBuffer(false);
  grab->ShouldRerenderOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

void OffscreenView::save_png(const std::filesystem::path& file) {
  write_png(capture(), file);
}

void write_png(vtkImageData* image, const std::filesystem::path& file) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  // Encoded in memory, then written whole through a temporary file: a full disk leaves no
  // half image, and is reported.
  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->WriteToMemoryOn();
  writer->SetInputData(image);
  writer->Write();
  vtkUnsignedCharArray* bytes = writer->GetResult();
  if (writer->GetErrorCode() != 0 || !bytes || bytes->GetNumberOfValues() == 0)
    throw std::runtime_error("cannot encode " + file.string());
  write_atomically(file, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(bytes->GetPointer(0)),
              std::streamsize(bytes->GetNumberOfValues()));
  });
}

vtkSmartPointer<vtkImageData> read_png(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) throw std::runtime_error("no such image: " + file.string());
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(reader->GetOutput());
  return image;
}

}  // namespace sedem::render
