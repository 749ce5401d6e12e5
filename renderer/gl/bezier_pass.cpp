#include "gl/bezier_pass.h"

#include "core/limits.h"

#include <algorithm>
#include <cstddef>
#include <string>

namespace radview::gl {

namespace {

// llvmpipe loses geometry past ~125k triangles per draw (gl/README.md, "Platform notes"); with these
// patches (8 vec4 of patch data each) it corrupts already at ~91k (level 32 and 64 on
// assets/discontinuities.gltf) and not at 75k. 50k keeps a margin.
constexpr size_t kMaxTrianglesPerDraw = 50'000;

// The net of the piece starting at `vertex`, unpacked as the shaders read it.
std::array<Rgb, 10> netOf(const BezierVertex& vertex) {
  std::array<Rgb, 10> net{};
  for (int i = 0; i < 10; ++i)
    for (int c = 0; c < 3; ++c) net[i][c] = vertex.control[(3 * i + c) / 4][(3 * i + c) % 4];
  return net;
}

// Triangles equal-spacing tessellation makes of a triangle whose levels are at most L, bounded
// above.
size_t trianglesAt(int L) { return size_t(L) * L + 3 * size_t(L); }

size_t trianglesOf(const TessellationLevels& l) {
  return trianglesAt(std::max({l.inner, l.outer[0], l.outer[1], l.outer[2]}));
}

}  // namespace

BezierPass::BezierPass() {
  glCreateVertexArrays(1, &vao_);
  glCreateBuffers(1, &vbo_);
  glVertexArrayVertexBuffer(vao_, 0, vbo_, 0, sizeof(BezierVertex));
  for (GLuint attribute = 0; attribute < 10; ++attribute) {
    const GLuint offset = attribute == 0 ? offsetof(BezierVertex, position)
                          : attribute == 1
                              ? offsetof(BezierVertex, beta)
                              : GLuint(offsetof(BezierVertex, control) + (attribute - 2) * sizeof(glm::vec4));
    glEnableVertexArrayAttrib(vao_, attribute);
    glVertexArrayAttribFormat(vao_, attribute, attribute < 2 ? 3 : 4, GL_FLOAT, GL_FALSE, offset);
    glVertexArrayAttribBinding(vao_, attribute, 0);
  }
  glCreateBuffers(1, &levelsVbo_);
  glVertexArrayVertexBuffer(vao_, 1, levelsVbo_, 0, sizeof(glm::vec4));
  glEnableVertexArrayAttrib(vao_, 10);
  glVertexArrayAttribFormat(vao_, 10, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao_, 10, 1);
  glCreateQueries(GL_PRIMITIVES_GENERATED, 2, primitiveQueries_.data());
}

BezierPass::~BezierPass() {
  glDeleteVertexArrays(1, &vao_);
  glDeleteBuffers(1, &vbo_);
  glDeleteBuffers(1, &levelsVbo_);
  glDeleteQueries(2, primitiveQueries_.data());
}

void BezierPass::upload(std::vector<BezierVertex> vertices, int degree) {
  glNamedBufferData(vbo_, vertices.size() * sizeof(BezierVertex), vertices.data(), GL_STATIC_DRAW);
  vertices_ = std::move(vertices);
  degree_ = degree;
  levelsFor_ = {-2, 0, 0};
}

void BezierPass::draw(const glm::mat4& clipFromWorld, const BezierEvaluation& evaluation) {
  const size_t patches = std::min(vertices_.size() / 3, evaluation.pieces);
  statistics_.patches = patches;
  glBindVertexArray(vao_);
  if (evaluation.tessellation == 0) {
    const ShaderProgram& perPixel = perPixel_[degree_ == 3];
    perPixel.set("clipFromWorld", clipFromWorld);
    perPixel.setViewportSize();
    perPixel.use();
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * patches));
    statistics_.draws = 1;
    statistics_.averageLevel = 1.0;
    statistics_.trianglesGenerated = patches;
    return;
  }

  if (frame_ >= 2) {
    GLuint64 generated = 0;
    GLint ready = 0;
    glGetQueryObjectiv(primitiveQueries_[frame_ % 2], GL_QUERY_RESULT_AVAILABLE, &ready);
    if (ready) {
      glGetQueryObjectui64v(primitiveQueries_[frame_ % 2], GL_QUERY_RESULT, &generated);
      statistics_.trianglesGenerated = size_t(generated);
    }
  }
  tessellated().set("clipFromWorld", clipFromWorld);
  tessellated().set("wireframe", 0);
  tessellated().set("shadeSurface", evaluation.surfaceHeight > 0.0 ? 1 : 0);
  glBeginQuery(GL_PRIMITIVES_GENERATED, primitiveQueries_[frame_ % 2]);
  size_t draws = 0;
  const double levelSum = drawTessellated(evaluation, draws);
  glEndQuery(GL_PRIMITIVES_GENERATED);
  ++frame_;
  statistics_.draws = draws;
  statistics_.averageLevel = patches ? levelSum / double(patches) : 0.0;
}

void BezierPass::drawTriangles(const glm::mat4& clipFromWorld, const BezierEvaluation& evaluation,
                               const glm::vec4& colour) {
  if (evaluation.tessellation == 0 || vertices_.empty()) return;
  glBindVertexArray(vao_);
  tessellated().set("clipFromWorld", clipFromWorld);
  tessellated().set("wireframe", 1);
  tessellated().set("wireColour", colour);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  size_t draws = 0;
  drawTessellated(evaluation, draws);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

void BezierPass::updateLevels(const BezierEvaluation& evaluation) {
  const std::array<double, 3> key = {double(evaluation.tessellation), evaluation.exposureScale, evaluation.tolerance};
  if (key == levelsFor_) return;
  const size_t patches = vertices_.size() / 3;
  std::vector<TessellationLevels> levels;
  if (evaluation.tessellation == kAdaptiveTessellation) {
    std::vector<std::array<Vec3, 3>> corners(patches);
    std::vector<std::array<Rgb, 10>> nets(patches);
    std::vector<const Rgb*> netPointers(patches);
    for (size_t p = 0; p < patches; ++p) {
      for (int c = 0; c < 3; ++c) corners[p][c] = Vec3(vertices_[3 * p + c].position);
      nets[p] = netOf(vertices_[3 * p]);
      netPointers[p] = nets[p].data();
    }
    levels = tessellationLevelsForPieces(degree_, corners, netPointers, evaluation.exposureScale, evaluation.tolerance);
  } else {
    const int L = evaluation.tessellation;
    levels.assign(patches, TessellationLevels{{L, L, L}, L});
  }
  // Before anything is drawn, and before levels_ changes (it must stay what levelsVbo_ holds): a
  // fine level over a large mesh would keep the GPU busy for hours.
  uint64_t triangles = 0;
  for (const TessellationLevels& l : levels) triangles += trianglesOf(l);
  checkLimit(
      "--tessellation " + (evaluation.tessellation == kAdaptiveTessellation ? std::string("adaptive")
                                                                            : std::to_string(evaluation.tessellation)),
      triangles, kMaxTessellatedTriangles, "triangles a frame from " + std::to_string(patches) + " Bezier pieces");
  levels_ = std::move(levels);
  std::vector<glm::vec4> perVertex;
  perVertex.reserve(3 * patches);
  for (const TessellationLevels& l : levels_)
    for (int c = 0; c < 3; ++c) perVertex.push_back(glm::vec4(l.outer[0], l.outer[1], l.outer[2], l.inner));
  glNamedBufferData(levelsVbo_, perVertex.size() * sizeof(glm::vec4), perVertex.data(), GL_DYNAMIC_DRAW);
  levelsFor_ = key;
}

double BezierPass::drawTessellated(const BezierEvaluation& evaluation, size_t& draws) {
  updateLevels(evaluation);
  const size_t patches = std::min(vertices_.size() / 3, evaluation.pieces);
  tessellated().set("heightScale", float(evaluation.surfaceHeight));
  tessellated().set("eye", evaluation.eye);
  tessellated().use();
  glPatchParameteri(GL_PATCH_VERTICES, 3);
  size_t first = 0;
  double levelSum = 0.0;
  while (first < patches) {
    size_t count = 0, triangles = 0;
    while (first + count < patches &&
           (count == 0 || triangles + trianglesOf(levels_[first + count]) <= kMaxTrianglesPerDraw)) {
      triangles += trianglesOf(levels_[first + count]);
      levelSum += levels_[first + count].inner;
      ++count;
    }
    glDrawArrays(GL_PATCHES, GLint(3 * first), GLsizei(3 * count));
    first += count;
    ++draws;
  }
  return levelSum;
}

}  // namespace radview::gl
