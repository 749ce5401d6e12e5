#pragma once
// Pass 3 of a frame: what is drawn over the tone-mapped image, depth-tested against the surfaces
// (MeshRenderer pushes their depth back first): element edges, the lines that split elements into
// Bezier pieces, the radiosity surface's control net (fig. 9.13), discontinuity edges coloured by
// continuity order, and T-vertex markers. Lines are one pixel wide: wide lines are not in the
// core profile.
#include "gl/buffer_storage.h"
#include "gl/gl_object.h"
#include "gl/shader_program.h"
#include "mesh/display_mesh.h"

#include <glm/glm.hpp>

#include <vector>

namespace radview::gl {

// Which overlays a frame shows.
struct OverlaySelection {
  bool elementEdges = false;
  bool splitLines = false;
  bool controlNet = false;
  bool discontinuityEdges = false;
  bool tVertices = false;
  glm::vec4 edgeColour{0.0f, 0.0f, 0.0f, 1.0f};
};

class OverlayPass {
 public:
  // `storage` holds the element edges' buffer and outlives the pass.
  explicit OverlayPass(BufferStorage& storage);

  // A mesh's overlays; with `keepElementEdges`, the element edges stay those of the last mesh.
  void setMesh(const DisplayMesh& display, bool keepElementEdges = false);
  void setSplitLines(const std::vector<glm::vec3>& lines);  // two points per segment
  void setControlNet(const std::vector<glm::vec3>& lines);

  // Whether `shown` has anything to draw.
  bool draws(const OverlaySelection& shown) const;
  // Into the bound framebuffer, over its depth, in two steps so that a caller's lines (the
  // tessellated triangles) lie between them: each step over what was drawn before where they
  // meet. The caller has set the depth test (GL_LEQUAL, depth writes off).
  void drawElementEdges(const OverlaySelection& shown, const glm::mat4& clipFromWorld) const;
  void drawPiecesAndMarkers(const OverlaySelection& shown, const glm::mat4& clipFromWorld) const;

  size_t tVertexCount() const { return size_t(tVertexMarkers_); }

 private:
  void drawLines(GLuint vao, GLsizei vertices, const glm::vec4& colour, const glm::mat4& clipFromWorld) const;

  BufferStorage& storage_;
  ShaderProgram linesProgram_{{"lines.vert", "lines.frag"}};
  ShaderProgram markersProgram_{{"overlay.vert", "overlay.frag"}};  // per-vertex colours
  GlObject edgeVao_, edgeVbo_, splitVao_, splitVbo_, netVao_, netVbo_;
  GlObject markerVao_, markerVbo_;  // the discontinuity edges, then the T-vertex markers
  GLsizei edgeVertices_ = 0, splitVertices_ = 0, netVertices_ = 0;
  GLsizei discontinuityVertices_ = 0, tVertexMarkers_ = 0;
};

}  // namespace radview::gl
