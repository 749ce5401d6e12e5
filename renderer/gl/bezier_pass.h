#pragma once
// Draws the Bezier pieces of the quadratic and C1 interpolants (patch_vertices.h), either
// evaluated exactly per pixel, or tessellated on the GPU at a fixed or adaptive level and
// interpolated linearly between generated vertices (C&W §9.2).
#include "gl/patch_vertices.h"
#include "gl/shader_program.h"
#include "interp/tessellation_level.h"

#include <epoxy/gl.h>

#include <array>
#include <cstdint>
#include <vector>

namespace radview::gl {

// How a Bezier piece reaches the pixels.
struct BezierEvaluation {
  // 0: exact per pixel (no tessellation); 1..64: tessellated at that level; -1: tessellated
  // at the adaptive level that keeps the display error under `tolerance`.
  int tessellation = 0;
  double tolerance = 0.5 / 255.0;  // display units (an 8-bit step is 1/255)
  double exposureScale = 1.0;      // 2^exposure, which the display error depends on
  // Radiosity surface (fig. 9.13): > 0 lifts each point off its element by this many world
  // units per unit of luminance, shaded for the eye at `eye`; needs tessellation.
  double surfaceHeight = 0.0;
  glm::vec3 eye{0.0f};
  // Draw only the first this many pieces (the rest are drawn by another pass).
  size_t pieces = SIZE_MAX;
};

inline constexpr int kAdaptiveTessellation = -1;

// What the last draw generated.
struct TessellationStatistics {
  size_t patches = 0;
  size_t draws = 0;               // one per batch (see BezierPass::draw)
  double averageLevel = 0.0;      // inner level; 1 for per pixel
  size_t trianglesGenerated = 0;  // GL_PRIMITIVES_GENERATED of the last draw whose query is ready
};

class BezierPass {
 public:
  BezierPass();
  ~BezierPass();
  BezierPass(const BezierPass&) = delete;
  BezierPass& operator=(const BezierPass&) = delete;

  void upload(std::vector<BezierVertex> vertices, int degree);
  // Into the bound framebuffer, depth-tested. Tessellated draws are split so that none
  // generates more than 50k triangles: past ~91k per draw llvmpipe corrupts these patches
  // (bezier_pass.cpp); the adaptive levels are computed on the CPU too for that.
  void draw(const glm::mat4& clipFromWorld, const BezierEvaluation& evaluation);
  // The generated triangles as lines of `colour` (the tessellation overlay), same levels as
  // draw(); nothing when evaluating per pixel.
  void drawTriangles(const glm::mat4& clipFromWorld, const BezierEvaluation& evaluation, const glm::vec4& colour);
  const TessellationStatistics& statistics() const { return statistics_; }
  const std::vector<BezierVertex>& vertices() const { return vertices_; }
  int degree() const { return degree_; }

 private:
  // One program per degree, quadratic [0] and cubic [1] (ShaderProgram: compile-time choices).
  ShaderProgram perPixel_[2] = {ShaderProgram({"bezier.vert", "bezier.frag"}, {"DEGREE 2"}),
                                ShaderProgram({"bezier.vert", "bezier.frag"}, {"DEGREE 3"})};
  const ShaderProgram& tessellated() const { return tessellated_[degree_ == 3]; }
  // Sets the per-patch levels for `evaluation` (when they change), then issues the tessellated
  // draws in batches; returns the inner-level sum of the patches.
  double drawTessellated(const BezierEvaluation& evaluation, size_t& draws);
  void updateLevels(const BezierEvaluation& evaluation);
  ShaderProgram tessellated_[2] = {
      ShaderProgram({"tessellated.vert", "tessellated.tesc", "tessellated.tese", "tessellated.frag"}, {"DEGREE 2"}),
      ShaderProgram({"tessellated.vert", "tessellated.tesc", "tessellated.tese", "tessellated.frag"}, {"DEGREE 3"})};
  GLuint vao_ = 0, vbo_ = 0, levelsVbo_ = 0;
  std::vector<BezierVertex> vertices_;
  std::vector<TessellationLevels> levels_;     // per patch, as uploaded to levelsVbo_
  std::array<double, 3> levelsFor_{-2, 0, 0};  // the tessellation, exposure scale, tolerance of levels_
  int degree_ = 3;
  std::array<GLuint, 2> primitiveQueries_{};
  int frame_ = 0;
  TessellationStatistics statistics_;
};

}  // namespace radview::gl
