#include "gl/deferred_pass.h"

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
}

DeferredPass::~DeferredPass() {
  GLuint arrays[] = {vao_, emptyVao_};
  glDeleteVertexArrays(2, arrays);
  GLuint buffers[] = {corners_, nets_};
  glDeleteBuffers(2, buffers);
  glDeleteTextures(1, &netsTexture_);
}

void DeferredPass::upload(const PatchNets& nets) {
  glNamedBufferData(corners_, nets.corners.size() * sizeof(glm::vec3), nets.corners.data(), GL_STATIC_DRAW);
  glNamedBufferData(nets_, nets.nets.size() * sizeof(glm::vec4), nets.nets.data(), GL_STATIC_DRAW);
  glTextureBuffer(netsTexture_, GL_RGBA32F, nets_);
  triangles_ = nets.triangles();
  degree_ = nets.degree;
}

void DeferredPass::draw(const glm::mat4& clipFromWorld, RenderTargets& targets, GLuint target) {
  // Pass 1: visibility and depth; 0 marks the background.
  const GLuint visibility = targets.ensureVisibility();
  const GLuint background[4] = {0, 0, 0, 0};
  glClearNamedFramebufferuiv(visibility, GL_COLOR, 0, background);
  glBindFramebuffer(GL_FRAMEBUFFER, visibility);
  visibility_.set("clipFromWorld", clipFromWorld);
  visibility_.use();
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * triangles_));

  // Pass 2: each covered pixel's value, into the target; the depth is pass 1's.
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  GLboolean depthTest = GL_FALSE;
  glGetBooleanv(GL_DEPTH_TEST, &depthTest);
  glDisable(GL_DEPTH_TEST);
  const ShaderProgram& resolve = resolve_[degree_ == 3];
  resolve.set("visibility", 0);
  resolve.set("nets", 1);
  resolve.use();
  glBindTextureUnit(0, targets.visibilityTexture());
  glBindTextureUnit(1, netsTexture_);
  glBindVertexArray(emptyVao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindTextureUnit(0, 0);
  glBindTextureUnit(1, 0);
  if (depthTest) glEnable(GL_DEPTH_TEST);
}

}  // namespace radview::gl
