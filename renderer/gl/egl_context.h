#pragma once
// A headless OpenGL 4.5 core context through EGL: Mesa's surfaceless platform where it exists
// (llvmpipe, no GPU), else the first EGL device that gives one (EGL_EXT_platform_device, as
// NVIDIA's driver offers). Rendering then goes to framebuffer objects.
#include <string>

namespace radview::gl {

class EglContext {
 public:
  // Throws Error saying which platforms were tried and why each failed. RADVIEW_EGL_PLATFORM
  // = "surfaceless" or "device" restricts the choice.
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // "EGL surfaceless: llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"
  const std::string& description() const { return description_; }

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string description_;
};

}  // namespace radview::gl
