#pragma once
// An image shown in place of a mesh's interpolated radiosity (the viewer's final gather, C&W
// §9.3.1): linear, any size, copied over pass 1's colour, stretched to the render's size (nearest
// texel), so that the tone map, the false-colour views and the overlays treat it as they treat a
// method's render.
#include "core/image.h"
#include "gl/gl_object.h"

namespace radview::gl {

class ShownImage {
 public:
  // Throws Error for a size this OpenGL cannot hold, leaving the image shown before.
  void set(const LinearImage& image);
  void clear();
  bool empty() const { return texture_ == 0; }
  // Copies the image over colour attachment 0 of `framebuffer`, at width x height.
  void copyTo(GLuint framebuffer, int width, int height) const;

 private:
  GlObject texture_, framebuffer_;  // the image, and a framebuffer to blit it from
  int width_ = 0, height_ = 0;
};

}  // namespace radview::gl
