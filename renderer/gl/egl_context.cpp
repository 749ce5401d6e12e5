#include "gl/egl_context.h"

#include "core/error.h"
#include "core/strings.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <cstring>
#include <vector>

namespace radview::gl {

namespace {

// Initialises `display` and makes a GL 4.5 core context current on it, or explains why not.
bool makeContext(EGLDisplay display, EGLContext& context, std::string& why) {
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
    why = "no display";
    return false;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    why = "no desktop OpenGL API";
    eglTerminate(display);
    return false;
  }
  const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configCount = 0;
  const bool noConfig = epoxy_has_egl_extension(display, "EGL_KHR_no_config_context");
  if (!noConfig && (!eglChooseConfig(display, configAttributes, &config, 1, &configCount) || configCount == 0)) {
    why = "no OpenGL-renderable config";
    eglTerminate(display);
    return false;
  }
  const EGLint contextAttributes[] = {
      EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  context = eglCreateContext(display, noConfig ? EGL_NO_CONFIG_KHR : config, EGL_NO_CONTEXT, contextAttributes);
  if (context == EGL_NO_CONTEXT) {
    why = "no OpenGL 4.5 core context (EGL error " + hexCode(eglGetError()) + ")";
    eglTerminate(display);
    return false;
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    why = "cannot make the context current without a surface";
    eglDestroyContext(display, context);
    eglTerminate(display);
    return false;
  }
  return true;
}

}  // namespace

EglContext::EglContext() {
  const char* only = std::getenv("RADVIEW_EGL_PLATFORM");
  const std::string choice = only ? only : "";
  if (!choice.empty() && choice != "surfaceless" && choice != "device")
    throw Error("RADVIEW_EGL_PLATFORM='" + choice + "': expected 'surfaceless' or 'device'");
  std::string tried;
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  std::string platform;

  if (choice != "device") {
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
      EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      std::string why;
      if (makeContext(d, context, why)) {
        display = d;
        platform = "EGL surfaceless";
      } else {
        tried += "surfaceless: " + why + "; ";
      }
    } else {
      tried += "surfaceless: not offered; ";
    }
  }
  if (display == EGL_NO_DISPLAY && choice != "surfaceless") {
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
      EGLint count = 0;
      eglQueryDevicesEXT(0, nullptr, &count);
      std::vector<EGLDeviceEXT> devices(static_cast<size_t>(std::max(count, 0)));
      if (count > 0) eglQueryDevicesEXT(count, devices.data(), &count);
      for (EGLint i = 0; i < count && display == EGL_NO_DISPLAY; ++i) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        std::string why;
        if (makeContext(d, context, why)) {
          display = d;
          platform = "EGL device " + std::to_string(i);
        } else {
          tried += "device " + std::to_string(i) + ": " + why + "; ";
        }
      }
      if (count <= 0) tried += "device: no EGL devices; ";
    } else {
      tried += "device: not offered; ";
    }
  }
  if (display == EGL_NO_DISPLAY) {
    if (!tried.empty()) tried.resize(tried.size() - 2);
    throw Error("headless OpenGL 4.5 through EGL is unavailable (" + tried + ")");
  }
  display_ = display;
  context_ = context;
  description_ = platform + ": " + reinterpret_cast<const char*>(glGetString(GL_RENDERER)) + ", OpenGL " +
                 reinterpret_cast<const char*>(glGetString(GL_VERSION));
}

EglContext::~EglContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

}  // namespace radview::gl
