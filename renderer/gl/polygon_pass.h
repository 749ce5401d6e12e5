#pragma once
// The methods evaluated per pixel from an element's whole polygon (shaders/polygon.frag):
// scanline Gouraud (C&W fig. 9.7), bilinear quads (fig. 9.9) and serendipity quads under the
// quadratic method. The elements' corners reach the shaders as buffer textures, built when a
// polygon method is first drawn.
#include "gl/buffer_storage.h"
#include "gl/gl_object.h"
#include "gl/shader_program.h"
#include "mesh/display_mesh.h"
#include "mesh/radiosity_mesh.h"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace radview::gl {

class PolygonPass {
 public:
  // What polygon.frag evaluates per pixel (its MODE_ macros).
  enum class Mode : int { Scanline = 0, Bilinear = 1, Serendipity = 2 };

  // `storage` holds the pass's buffers and outlives it.
  explicit PolygonPass(BufferStorage& storage);

  // A new mesh, as drawn; its polygons are built when first drawn. The serendipity quads'
  // triangles stay until setTriangles.
  void setMesh(std::shared_ptr<const RadiosityMesh> mesh);
  // The mesh's display triangles: the serendipity quads' are kept for drawSerendipity.
  void setTriangles(const std::vector<DisplayVertex>& triangles);

  // `mode` over the DisplayVertex triangles in `vao`, into the bound framebuffer. Throws Error
  // where the corners outgrow this OpenGL's buffer textures.
  void draw(Mode mode, GLuint vao, GLsizei vertices, const glm::mat4& clipFromWorld, int width, int height);
  // The serendipity quads, exact per pixel.
  void drawSerendipity(const glm::mat4& clipFromWorld, int width, int height);
  GLsizei serendipityVertices() const { return serendipityVertices_; }

 private:
  void uploadPolygons();
  // Each mode reading the element's corners per pixel; scanline and bilinear also reading a
  // triangle's or quad's per vertex, as flat outputs (CORNERS_PER_VERTEX; draw picks); scanline
  // Gouraud also for meshes with larger polygons (LARGE_POLYGONS).
  static ShaderProgram program(const char* mode, bool cornersPerVertex, bool largePolygons = false);

  BufferStorage& storage_;
  std::shared_ptr<const RadiosityMesh> mesh_;
  ShaderProgram perPixel_[3] = {program("MODE_SCANLINE", false), program("MODE_BILINEAR", false),
                                program("MODE_SERENDIPITY", false)};
  ShaderProgram perVertex_[2] = {program("MODE_SCANLINE", true), program("MODE_BILINEAR", true)};
  ShaderProgram largeScanline_[2] = {program("MODE_SCANLINE", false, true),
                                     program("MODE_SCANLINE", true, true)};  // [per vertex]
  GlObject corners_{GlKind::Buffer}, offsets_{GlKind::Buffer};               // lib/polygon_corners.glsl
  GlObject cornerTexels_{GlKind::TextureBuffer}, offsetTexels_{GlKind::TextureBuffer};
  bool uploaded_ = false;       // only the methods that draw polygons need them
  bool largePolygons_ = false;  // any element of more than four corners
  GlObject serendipityVao_, serendipityVbo_;
  GLsizei serendipityVertices_ = 0;
};

}  // namespace radview::gl
