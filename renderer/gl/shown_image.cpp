#include "gl/shown_image.h"

#include "gl/image_transfer.h"

namespace radview::gl {

void ShownImage::set(const LinearImage& image) {
  GlObject texture = linearTexture(image, "the shown image");
  clear();
  texture_ = std::move(texture);
  framebuffer_ = GlObject(GlKind::Framebuffer);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, texture_, 0);
  width_ = image.width;
  height_ = image.height;
}

void ShownImage::clear() {
  framebuffer_.reset();
  texture_.reset();
  width_ = height_ = 0;
}

void ShownImage::copyTo(GLuint framebuffer, int width, int height) const {
  glBlitNamedFramebuffer(framebuffer_, framebuffer, 0, 0, width_, height_, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                         GL_NEAREST);
}

}  // namespace radview::gl
