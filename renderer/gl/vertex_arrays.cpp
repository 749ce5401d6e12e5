#include "gl/vertex_arrays.h"

#include "mesh/display_mesh.h"

namespace radview::gl {

void createVertexArray(GlObject& vao, GlObject& vbo, GLsizei stride) {
  vao = GlObject(GlKind::VertexArray);
  vbo = GlObject(GlKind::Buffer);
  glVertexArrayVertexBuffer(vao, 0, vbo, 0, stride);
}

void floatAttribute(GLuint vao, GLuint index, GLint components, size_t offset) {
  glEnableVertexArrayAttrib(vao, index);
  glVertexArrayAttribFormat(vao, index, components, GL_FLOAT, GL_FALSE, GLuint(offset));
  glVertexArrayAttribBinding(vao, index, 0);
}

void createDisplayVertexArray(GlObject& vao, GlObject& vbo) {
  createVertexArray(vao, vbo, sizeof(DisplayVertex));
  floatAttribute(vao, 0, 3, offsetof(DisplayVertex, position));
  floatAttribute(vao, 1, 3, offsetof(DisplayVertex, B));
  floatAttribute(vao, 2, 3, offsetof(DisplayVertex, Bflat));
  glEnableVertexArrayAttrib(vao, 3);
  glVertexArrayAttribIFormat(vao, 3, 1, GL_UNSIGNED_INT, offsetof(DisplayVertex, element));
  glVertexArrayAttribBinding(vao, 3, 0);
}

}  // namespace radview::gl
