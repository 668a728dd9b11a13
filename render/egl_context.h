#pragma once

namespace sedem::render {

// An OpenGL 3.2+ core context on Mesa's EGL surfaceless platform, made current on the
// calling thread. It has no window and no default framebuffer: VTK draws into its own
// framebuffer objects (vtkGenericOpenGLRenderWindow). Throws std::runtime_error with the
// EGL call that failed.
class EglContext {
 public:
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void make_current();

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace sedem::render
