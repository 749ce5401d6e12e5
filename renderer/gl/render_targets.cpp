#include "gl/render_targets.h"

#include "core/error.h"
#include "core/strings.h"

#include <algorithm>
#include <string>

namespace radview::gl {

namespace {

GLuint texture(GLenum format, int width, int height) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, format, width, height);
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

void requireComplete(GLuint fbo, const char* name) {
  const GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error(std::string("OpenGL: the ") + name + " framebuffer is incomplete (status " + hexCode(status) + ")");
}

}  // namespace

RenderTargets::~RenderTargets() { release(); }

void RenderTargets::release() {
  glDeleteFramebuffers(1, &linearFbo_);
  glDeleteFramebuffers(1, &displayFbo_);
  glDeleteFramebuffers(1, &comparisonFbo_);
  GLuint textures[] = {linearColour_, displayColour_, depth_, comparisonColour_};
  glDeleteTextures(4, textures);
  linearFbo_ = displayFbo_ = linearColour_ = displayColour_ = depth_ = comparisonFbo_ = comparisonColour_ = 0;
  width_ = height_ = 0;
}

void RenderTargets::resize(int width, int height) {
  if (width == width_ && height == height_ && linearFbo_) return;
  // The targets are textures attached to framebuffers: both of this context's limits apply, on
  // top of radview's own (core/limits.h, checked where the size is given).
  GLint maxTexture = 0, maxWidth = 0, maxHeight = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &maxWidth);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &maxHeight);
  if (width <= 0 || height <= 0 || width > std::min(maxTexture, maxWidth) || height > std::min(maxTexture, maxHeight))
    throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                " is more than this OpenGL can draw into: " + std::to_string(std::min(maxTexture, maxWidth)) + "x" +
                std::to_string(std::min(maxTexture, maxHeight)) +
                " (GL_MAX_TEXTURE_SIZE, GL_MAX_FRAMEBUFFER_WIDTH/HEIGHT)");
  release();
  linearColour_ = texture(GL_RGBA32F, width, height);
  displayColour_ = texture(GL_RGBA8, width, height);
  depth_ = texture(GL_DEPTH_COMPONENT32F, width, height);
  glCreateFramebuffers(1, &linearFbo_);
  glNamedFramebufferTexture(linearFbo_, GL_COLOR_ATTACHMENT0, linearColour_, 0);
  glNamedFramebufferTexture(linearFbo_, GL_DEPTH_ATTACHMENT, depth_, 0);
  glCreateFramebuffers(1, &displayFbo_);
  glNamedFramebufferTexture(displayFbo_, GL_COLOR_ATTACHMENT0, displayColour_, 0);
  glNamedFramebufferTexture(displayFbo_, GL_DEPTH_ATTACHMENT, depth_, 0);
  try {
    requireComplete(linearFbo_, "linear");
    requireComplete(displayFbo_, "display");
  } catch (const Error&) {
    release();  // width_ stays 0, so the next resize tries again
    throw;
  }
  width_ = width;
  height_ = height;
}

GLuint RenderTargets::ensureWithDepth(GLenum format, GLuint& colour, GLuint& fbo, const char* name) {
  if (fbo) return fbo;
  colour = texture(format, width_, height_);
  glCreateFramebuffers(1, &fbo);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, colour, 0);
  glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth_, 0);
  requireComplete(fbo, name);
  return fbo;
}

GLuint RenderTargets::ensureComparison() {
  return ensureWithDepth(GL_RGBA32F, comparisonColour_, comparisonFbo_, "comparison");
}

}  // namespace radview::gl
