#include "gl/deferred_pass.h"

#include "core/error.h"

#include <string>
#include <vector>

namespace radview::gl {

DeferredPass::DeferredPass() {
  glCreateVertexArrays(1, &vao_);
  glCreateBuffers(1, &corners_);
  glVertexArrayVertexBuffer(vao_, 0, corners_, 0, sizeof(glm::vec3));
  glEnableVertexArrayAttrib(vao_, 0);
  glVertexArrayAttribFormat(vao_, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao_, 0, 0);
  glCreateBuffers(1, &nets_);
  glCreateTextures(GL_TEXTURE_BUFFER, 1, &netsTexture_);
  glCreateVertexArrays(1, &emptyVao_);
  // The one pass: the corners, and from each vertex's corner's 48 bytes on, its own values
  // (and the first vertex's the other corners' for C1 quadratic: c1_forward.vert).
  struct Attribute {
    GLint size;
    GLuint offset;
  };
  const std::vector<Attribute> attributes[2] = {{{4, 0}, {4, 16}, {4, 32}, {4, 72}, {4, 120}},
                                                {{4, 0}, {4, 16}, {4, 32}}};
  for (int cubic = 0; cubic < 2; ++cubic) {
    GLuint& vao = oneCornerVao_[cubic];
    glCreateVertexArrays(1, &vao);
    glVertexArrayVertexBuffer(vao, 0, corners_, 0, sizeof(glm::vec3));
    glVertexArrayVertexBuffer(vao, 1, nets_, 0, GLsizei(kNetVec4s / 3 * sizeof(glm::vec4)));
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, 0, 0);
    for (size_t a = 0; a < attributes[cubic].size(); ++a) {
      glEnableVertexArrayAttrib(vao, GLuint(a + 1));
      glVertexArrayAttribFormat(vao, GLuint(a + 1), attributes[cubic][a].size, GL_FLOAT, GL_FALSE,
                                attributes[cubic][a].offset);
      glVertexArrayAttribBinding(vao, GLuint(a + 1), 1);
    }
  }
}

DeferredPass::~DeferredPass() {
  GLuint arrays[] = {vao_, emptyVao_, oneCornerVao_[0], oneCornerVao_[1]};
  glDeleteVertexArrays(4, arrays);
  GLuint buffers[] = {corners_, nets_};
  glDeleteBuffers(2, buffers);
  glDeleteTextures(1, &netsTexture_);
}

void DeferredPass::upload(size_t triangles, int degree, const NetFill& fill) {
  const std::string pieces = std::string("per-pixel ") + (degree == 3 ? "Clough-Tocher" : "C1 quadratic") + ": ";
  const size_t vec4s = kNetVec4s;
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  if (triangles >= kMaxTriangles)
    throw Error(pieces + std::to_string(triangles) + " triangles, more than the " + std::to_string(kMaxTriangles - 1) +
                " its visibility pass can number");
  if (triangles * vec4s > size_t(maxTexels))
    throw Error(pieces + std::to_string(triangles) + " triangles need " + std::to_string(triangles * vec4s) +
                " texels of control values, more than this OpenGL's buffer textures hold (" +
                std::to_string(maxTexels) + ", GL_MAX_TEXTURE_BUFFER_SIZE)");
  const GLsizeiptr cornerBytes = GLsizeiptr(3 * triangles * sizeof(glm::vec3));
  // One triangle more: the one pass's last vertex reads up to 88 bytes past its triangle's.
  const GLsizeiptr netBytes = GLsizeiptr(vec4s * (triangles + 1) * sizeof(glm::vec4));
  // Written where the GL reads them: the CPU keeps no copy of its own.
  triangles_ = 0;  // until written
  try {
    auto* corners = reinterpret_cast<glm::vec3*>(storage_.reserve(corners_, size_t(cornerBytes)));
    auto* nets = reinterpret_cast<glm::vec4*>(storage_.reserve(nets_, size_t(netBytes)));
    fill(corners, nets);
    storage_.commit(corners_);
    storage_.commit(nets_);
  } catch (const Error& e) {
    throw Error(pieces + std::to_string(triangles) + " triangles' control values: " + e.what());
  }
  glTextureBuffer(netsTexture_, GL_RGBA32F, nets_);
  triangles_ = triangles;
  degree_ = degree;
}

void DeferredPass::clear() {
  storage_.clear(corners_);
  storage_.clear(nets_);
  triangles_ = 0;
}

void DeferredPass::draw(const glm::mat4& clipFromWorld, GLuint target) {
  // Each vertex reads its triangle's values once where the deferred pass reads them once per
  // covered pixel: fewer reads while there are fewer vertices than pixels (hidden surfaces are
  // evaluated too, but a scene's depth complexity is small beside the difference).
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  if (3 * triangles_ < size_t(viewport[2]) * size_t(viewport[3]))
    drawForward(clipFromWorld, target);
  else
    drawDeferred(clipFromWorld, target);
}

void DeferredPass::drawDepth(const glm::mat4& clipFromWorld) {
  visibility_.set("clipFromWorld", clipFromWorld);
  visibility_.setViewportSize();
  visibility_.use();
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * triangles_));
}

void DeferredPass::drawForward(const glm::mat4& clipFromWorld, GLuint target) {
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  const ShaderProgram& program = forward_[degree_ == 3];
  program.set("clipFromWorld", clipFromWorld);
  program.setViewportSize();
  program.use();
  glBindVertexArray(oneCornerVao_[degree_ == 3]);
  // C1 quadratic's flat outputs are those of the vertex that reads all three corners.
  if (degree_ == 2) glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * triangles_));
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
}

void DeferredPass::drawDeferred(const glm::mat4& clipFromWorld, GLuint target) {
  GLint colour = 0;
  glGetNamedFramebufferAttachmentParameteriv(target, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                                             &colour);
  glBindFramebuffer(GL_FRAMEBUFFER, target);

  // Pass 1: visibility and depth, into the target's colour.
  drawDepth(clipFromWorld);

  // Pass 2: each covered pixel's value over what pass 1 left there. A fragment that reads only
  // the texel it writes may sample its own render target once pass 1's writes are made visible
  // (OpenGL 4.5 §9.3.1, texture barrier).
  glTextureBarrier();
  GLboolean depthTest = GL_FALSE;
  glGetBooleanv(GL_DEPTH_TEST, &depthTest);
  glDisable(GL_DEPTH_TEST);
  const ShaderProgram& resolve = resolve_[degree_ == 3];
  resolve.set("visibility", 0);
  resolve.set("nets", 1);
  resolve.use();
  glBindTextureUnit(0, GLuint(colour));
  glBindTextureUnit(1, netsTexture_);
  glBindVertexArray(emptyVao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindTextureUnit(0, 0);
  glBindTextureUnit(1, 0);
  if (depthTest) glEnable(GL_DEPTH_TEST);
}

}  // namespace radview::gl
