#pragma once
// Vertex arrays over one buffer each, as the passes lay them out.
#include "gl/gl_object.h"

#include <epoxy/gl.h>

#include <cstddef>

namespace radview::gl {

// A vertex array reading one buffer of `stride`-byte vertices, and the buffer.
void createVertexArray(GlObject& vao, GlObject& vbo, GLsizei stride);

// Float attribute `index` of `components` at byte `offset` in each vertex.
void floatAttribute(GLuint vao, GLuint index, GLint components, size_t offset);

// A vertex array of DisplayVertex triangles (mesh/display_mesh.h), and its buffer.
void createDisplayVertexArray(GlObject& vao, GlObject& vbo);

}  // namespace radview::gl
