#include "gl/image_transfer.h"

#include "core/error.h"

#include <algorithm>

namespace radview::gl {

namespace {

// Rows of `width` RGBA pixels in the opposite order.
template <typename T>
std::vector<T> flipRows(const std::vector<T>& pixels, int width, int height) {
  std::vector<T> rows(pixels.size());
  const size_t row = size_t(width) * 4;
  for (int y = 0; y < height; ++y) std::copy_n(&pixels[size_t(height - 1 - y) * row], row, &rows[size_t(y) * row]);
  return rows;
}

template <typename T>
std::vector<T> readPixels(GLuint framebuffer, GLenum colourBuffer, int width, int height, GLenum type) {
  std::vector<T> pixels(size_t(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glReadBuffer(colourBuffer);
  glReadPixels(0, 0, width, height, GL_RGBA, type, pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return flipRows(pixels, width, height);
}

}  // namespace

std::vector<uint8_t> readBytePixels(GLuint framebuffer, GLenum colourBuffer, int width, int height) {
  return readPixels<uint8_t>(framebuffer, colourBuffer, width, height, GL_UNSIGNED_BYTE);
}

std::vector<float> readFloatPixels(GLuint framebuffer, GLenum colourBuffer, int width, int height) {
  return readPixels<float>(framebuffer, colourBuffer, width, height, GL_FLOAT);
}

GlObject linearTexture(const LinearImage& image, const std::string& source) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (image.width < 1 || image.height < 1 || image.width > maxSize || image.height > maxSize)
    throw Error(source, "the image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                            ", outside this OpenGL's 1.." + std::to_string(maxSize));
  const std::vector<float> rows = flipRows(image.rgba, image.width, image.height);
  GlObject texture(GlKind::Texture2D);
  glTextureStorage2D(texture, 1, GL_RGBA32F, image.width, image.height);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureSubImage2D(texture, 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT, rows.data());
  return texture;
}

}  // namespace radview::gl
