#pragma once
// The methods the rasteriser draws itself (shaders/mesh.frag): flat and Gouraud on the display
// mesh's triangles, perspective-correct or, as classic hardware did, linear in screen space
// (C&W §9.2, note 3). Its vertex array of DisplayVertex triangles is also what the polygon pass
// rasterises the per-pixel polygon methods over.
#include "gl/buffer_storage.h"
#include "gl/gl_object.h"
#include "gl/shader_program.h"
#include "interp/method_registry.h"
#include "mesh/display_mesh.h"

#include <glm/glm.hpp>

#include <vector>

namespace radview::gl {

class RasterPass {
 public:
  // `storage` holds the triangles' buffer and outlives the pass.
  explicit RasterPass(BufferStorage& storage);

  // The display mesh's triangles; the first `linearForQuadratic` vertices are the linear
  // elements', which the quadratic method per pixel draws as Gouraud does.
  void setMesh(const std::vector<DisplayVertex>& triangles, size_t linearForQuadratic);
  // `method` (flat or Gouraud) over the first `vertices` vertices, into the bound framebuffer.
  void draw(Method method, bool perspectiveCorrect, const glm::mat4& clipFromWorld, GLsizei vertices) const;

  GLuint vertexArray() const { return vao_; }
  GLsizei vertices() const { return vertices_; }
  GLsizei linearForQuadraticVertices() const { return linearForQuadratic_; }

 private:
  BufferStorage& storage_;
  ShaderProgram program_{{"mesh.vert", "mesh.frag"}};
  GlObject vao_, vbo_;
  GLsizei vertices_ = 0, linearForQuadratic_ = 0;
};

}  // namespace radview::gl
