#include "gl/polygon_pass.h"

#include "core/error.h"
#include "gl/vertex_arrays.h"
#include "interp/interpolant.h"

#include <cstdint>
#include <string>

namespace radview::gl {

ShaderProgram PolygonPass::program(const char* mode, bool cornersPerVertex, bool largePolygons) {
  return ShaderProgram(
      {"polygon.vert", "polygon.frag"},
      {std::string("MODE ") + mode, std::string("CORNERS_PER_VERTEX ") + (cornersPerVertex ? "1" : "0"),
       std::string("LARGE_POLYGONS ") + (largePolygons ? "1" : "0")});
}

PolygonPass::PolygonPass(BufferStorage& storage) : storage_(storage) {
  createDisplayVertexArray(serendipityVao_, serendipityVbo_);
}

void PolygonPass::setMesh(std::shared_ptr<const RadiosityMesh> mesh) {
  mesh_ = std::move(mesh);
  storage_.clear(corners_);  // uploaded when first drawn
  storage_.clear(offsets_);
  uploaded_ = false;
}

void PolygonPass::setTriangles(const std::vector<DisplayVertex>& triangles) {
  std::vector<DisplayVertex> serendipity;
  for (const DisplayVertex& v : triangles)
    if (isSerendipityQuad(*mesh_, v.element)) serendipity.push_back(v);
  storage_.upload(serendipityVbo_, serendipity.data(), serendipity.size() * sizeof(DisplayVertex));
  serendipityVertices_ = static_cast<GLsizei>(serendipity.size());
}

void PolygonPass::uploadPolygons() {
  // Per corner three texels: position, B, and the B of the mid-edge node after it (serendipity
  // quads only); offsets[e] .. offsets[e+1] are element e's.
  std::vector<glm::vec4> corners;
  std::vector<uint32_t> offsets{0};
  offsets.reserve(mesh_->elements.size() + 1);
  largePolygons_ = false;
  for (size_t e = 0; e < mesh_->elements.size(); ++e) {
    const Element& element = mesh_->elements[e];
    const bool quad = isSerendipityQuad(*mesh_, e);
    largePolygons_ = largePolygons_ || element.corners.size() > 4;
    for (size_t k = 0; k < element.corners.size(); ++k) {
      const Node& node = mesh_->nodes[element.corners[k]];
      corners.push_back(glm::vec4(glm::vec3(node.position), 1.0f));
      corners.push_back(glm::vec4(glm::vec3(node.B), 1.0f));
      corners.push_back(quad ? glm::vec4(glm::vec3(mesh_->nodes[element.midEdge[k]].B), 1.0f) : glm::vec4(0.0f));
    }
    offsets.push_back(uint32_t(corners.size() / 3));
  }
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  if (corners.size() > size_t(maxTexels))
    throw Error("element polygons: " + std::to_string(corners.size() / 3) + " corners need " +
                std::to_string(corners.size()) + " texels, more than this OpenGL's buffer textures hold (" +
                std::to_string(maxTexels) + ", GL_MAX_TEXTURE_BUFFER_SIZE)");
  storage_.upload(corners_, corners.data(), corners.size() * sizeof(glm::vec4));
  storage_.upload(offsets_, offsets.data(), offsets.size() * sizeof(uint32_t));
  glTextureBuffer(cornerTexels_, GL_RGBA32F, corners_);
  glTextureBuffer(offsetTexels_, GL_R32UI, offsets_);
  uploaded_ = true;
}

void PolygonPass::draw(Mode mode, GLuint vao, GLsizei vertices, const glm::mat4& clipFromWorld, int width, int height) {
  if (!uploaded_) uploadPolygons();
  // A vertex reads its element's corners once where a pixel would read them for every covered
  // pixel: fewer reads while the draw has fewer vertices than the image has pixels, more beyond
  // (radview_scale_bench times both sides of the switch).
  const bool perVertex = mode != Mode::Serendipity && int64_t(vertices) < int64_t(width) * height;
  const ShaderProgram& program = mode == Mode::Scanline && largePolygons_ ? largeScanline_[perVertex]
                                 : perVertex                              ? perVertex_[int(mode)]
                                                                          : perPixel_[int(mode)];
  program.set("clipFromWorld", clipFromWorld);
  program.set("viewportSize", glm::vec2(width, height));
  program.use();
  glBindTextureUnit(2, cornerTexels_);
  glBindTextureUnit(3, offsetTexels_);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, vertices);
  glBindTextureUnit(2, 0);
  glBindTextureUnit(3, 0);
}

void PolygonPass::drawSerendipity(const glm::mat4& clipFromWorld, int width, int height) {
  if (serendipityVertices_ > 0)
    draw(Mode::Serendipity, serendipityVao_, serendipityVertices_, clipFromWorld, width, height);
}

}  // namespace radview::gl
