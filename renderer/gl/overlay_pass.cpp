#include "gl/overlay_pass.h"

#include "gl/vertex_arrays.h"

#include <cstddef>

namespace radview::gl {

namespace {

void createLineArray(GlObject& vao, GlObject& vbo) {
  createVertexArray(vao, vbo, sizeof(glm::vec3));
  floatAttribute(vao, 0, 3, 0);
}

}  // namespace

OverlayPass::OverlayPass(BufferStorage& storage) : storage_(storage) {
  createLineArray(edgeVao_, edgeVbo_);
  createLineArray(splitVao_, splitVbo_);
  createLineArray(netVao_, netVbo_);
  createVertexArray(markerVao_, markerVbo_, sizeof(OverlayVertex));
  floatAttribute(markerVao_, 0, 3, offsetof(OverlayVertex, position));
  floatAttribute(markerVao_, 1, 4, offsetof(OverlayVertex, colour));
}

void OverlayPass::setMesh(const DisplayMesh& display, bool keepElementEdges) {
  if (!keepElementEdges) {
    storage_.upload(edgeVbo_, display.elementEdges.data(), display.elementEdges.size() * sizeof(glm::vec3));
    edgeVertices_ = static_cast<GLsizei>(display.elementEdges.size());
  }
  std::vector<OverlayVertex> markers = display.discontinuityEdges;
  markers.insert(markers.end(), display.tVertices.begin(), display.tVertices.end());
  glNamedBufferData(markerVbo_, markers.size() * sizeof(OverlayVertex), markers.data(), GL_STATIC_DRAW);
  discontinuityVertices_ = static_cast<GLsizei>(display.discontinuityEdges.size());
  tVertexMarkers_ = static_cast<GLsizei>(display.tVertices.size());
}

void OverlayPass::setSplitLines(const std::vector<glm::vec3>& lines) {
  glNamedBufferData(splitVbo_, lines.size() * sizeof(glm::vec3), lines.data(), GL_STATIC_DRAW);
  splitVertices_ = static_cast<GLsizei>(lines.size());
}

void OverlayPass::setControlNet(const std::vector<glm::vec3>& lines) {
  glNamedBufferData(netVbo_, lines.size() * sizeof(glm::vec3), lines.data(), GL_STATIC_DRAW);
  netVertices_ = static_cast<GLsizei>(lines.size());
}

bool OverlayPass::draws(const OverlaySelection& shown) const {
  return (shown.elementEdges && edgeVertices_ > 0) || (shown.splitLines && splitVertices_ > 0) ||
         (shown.controlNet && netVertices_ > 0) || (shown.discontinuityEdges && discontinuityVertices_ > 0) ||
         (shown.tVertices && tVertexMarkers_ > 0);
}

void OverlayPass::drawLines(GLuint vao, GLsizei vertices, const glm::vec4& colour,
                            const glm::mat4& clipFromWorld) const {
  if (vertices == 0) return;
  linesProgram_.set("clipFromWorld", clipFromWorld);
  linesProgram_.set("colour", colour);
  linesProgram_.use();
  glBindVertexArray(vao);
  glDrawArrays(GL_LINES, 0, vertices);
}

void OverlayPass::drawElementEdges(const OverlaySelection& shown, const glm::mat4& clipFromWorld) const {
  if (shown.elementEdges) drawLines(edgeVao_, edgeVertices_, shown.edgeColour, clipFromWorld);
}

void OverlayPass::drawPiecesAndMarkers(const OverlaySelection& shown, const glm::mat4& clipFromWorld) const {
  if (shown.splitLines) drawLines(splitVao_, splitVertices_, kSplitLineColour, clipFromWorld);
  if (shown.controlNet) drawLines(netVao_, netVertices_, kControlNetColour, clipFromWorld);
  const bool edges = shown.discontinuityEdges && discontinuityVertices_ > 0;
  const bool markers = shown.tVertices && tVertexMarkers_ > 0;
  if (!edges && !markers) return;
  glEnable(GL_PROGRAM_POINT_SIZE);
  markersProgram_.set("clipFromWorld", clipFromWorld);
  markersProgram_.set("pointSize", 7.0f);
  markersProgram_.use();
  glBindVertexArray(markerVao_);
  // The discontinuity edges over the element edges, so that their colour wins.
  if (edges) glDrawArrays(GL_LINES, 0, discontinuityVertices_);
  if (markers) glDrawArrays(GL_POINTS, discontinuityVertices_, tVertexMarkers_);
  glDisable(GL_PROGRAM_POINT_SIZE);
}

}  // namespace radview::gl
