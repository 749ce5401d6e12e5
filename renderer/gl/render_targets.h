#pragma once
// The renderer's own framebuffers: `linear` holds radiosity as rendered (RGBA32F, alpha marks
// covered pixels) and depth; `display` holds the tone-mapped image (RGBA8) and shares that
// depth so overlays drawn after tone mapping are hidden by surfaces in front of them.
// A window presents `display`; a headless render reads it back. Both see the same pixels.
// `comparison`, made on first use, is a second linear target of the same size: the method a
// difference view compares with is drawn there first.
#include <epoxy/gl.h>

namespace radview::gl {

class RenderTargets {
 public:
  RenderTargets() = default;
  ~RenderTargets();
  RenderTargets(const RenderTargets&) = delete;
  RenderTargets& operator=(const RenderTargets&) = delete;

  // (Re)allocates when the size changes. Throws Error if the framebuffers are incomplete.
  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }
  GLuint linearFramebuffer() const { return linearFbo_; }
  GLuint displayFramebuffer() const { return displayFbo_; }
  GLuint linearTexture() const { return linearColour_; }
  // The comparison target, sharing the depth buffer (each pass clears it), made on the first
  // call. Throws Error as resize.
  GLuint ensureComparison();
  GLuint comparisonFramebuffer() const { return comparisonFbo_; }  // 0 until ensureComparison
  GLuint comparisonTexture() const { return comparisonColour_; }

 private:
  void release();
  // `fbo` with a new `format` texture as `colour` and the shared depth, unless made already.
  GLuint ensureWithDepth(GLenum format, GLuint& colour, GLuint& fbo, const char* name);
  int width_ = 0, height_ = 0;
  GLuint linearFbo_ = 0, displayFbo_ = 0;
  GLuint linearColour_ = 0, displayColour_ = 0, depth_ = 0;
  GLuint comparisonFbo_ = 0, comparisonColour_ = 0;
};

}  // namespace radview::gl
