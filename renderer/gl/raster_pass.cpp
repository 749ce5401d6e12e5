#include "gl/raster_pass.h"

#include "gl/vertex_arrays.h"

namespace radview::gl {

RasterPass::RasterPass(BufferStorage& storage) : storage_(storage) { createDisplayVertexArray(vao_, vbo_); }

void RasterPass::setMesh(const std::vector<DisplayVertex>& triangles, size_t linearForQuadratic) {
  storage_.upload(vbo_, triangles.data(), triangles.size() * sizeof(DisplayVertex));
  vertices_ = static_cast<GLsizei>(triangles.size());
  linearForQuadratic_ = static_cast<GLsizei>(linearForQuadratic);
}

void RasterPass::draw(Method method, bool perspectiveCorrect, const glm::mat4& clipFromWorld, GLsizei vertices) const {
  program_.set("clipFromWorld", clipFromWorld);
  program_.set("method", static_cast<int>(method));
  program_.set("perspectiveCorrect", perspectiveCorrect ? 1 : 0);
  program_.use();
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, vertices);
}

}  // namespace radview::gl
