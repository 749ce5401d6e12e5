#pragma once
// The C1 interpolants as the GPU draws them per pixel: every Bezier piece (3 per
// Clough-Tocher triangle, 6 per Powell-Sabin triangle) as its own triangle, each vertex
// carrying the piece's barycentric corner and the piece's control values. The control
// values are the same at the three vertices, so the fragment shader receives them as flat
// varyings: on llvmpipe that costs about what Gouraud costs, where fetching them from a
// buffer by primitive id costs 2.5 times as much (gl/README.md, "Platform notes"). No OpenGL here.
#include "interp/c1_patches.h"
#include "mesh/topology.h"

#include <glm/glm.hpp>

#include <vector>

namespace radview::gl {

struct BezierVertex {
  glm::vec3 position;
  glm::vec3 beta;  // the vertex's barycentric coordinates in its piece: (1,0,0), (0,1,0), (0,0,1)
  // RGB of the control values b_ijk in bezierIndex order: 10 (cubic) or 6 (quadratic), packed
  // three floats each into 8 vec4.
  glm::vec4 control[8];
};

// Quadratic Lagrange elements (C&W §9.2) as quadratic Bezier nets: a 6-node triangle with
// corner values f_i and mid-edge values m_ij is the net b_200 = f_0, b_110 = 2 m_01 - (f_0 +
// f_1) / 2, ... Other elements are drawn linear (over their watertightTriangles), as
// the degree-2 net of a linear function. Serendipity quads (isSerendipityQuad) are not
// triangle patches: their linear pieces come last, from piece *serendipityStart on, so the
// per-pixel path can leave them to the polygon pass that evaluates them exactly, while the
// radiosity surface, which needs pieces to lift, still has them (drawn linear there).
std::vector<BezierVertex> quadraticLagrangeVertices(const RadiosityMesh& mesh, const MeshTopology& topology,
                                                    size_t* serendipityStart = nullptr);
// Only the 6-node triangles' pieces: the quadratic method per pixel draws the rest of a mesh as
// the linear interpolant it is there, over the display triangles (MeshRenderer).
std::vector<BezierVertex> quadraticTriangleVertices(const RadiosityMesh& mesh);
std::vector<BezierVertex> cloughTocherVertices(const std::vector<CloughTocherPatch>& patches);

// The lines that split an element into its pieces, two points per segment, written at `out`:
// Clough-Tocher corners to the centroid; Powell-Sabin incenter to the corners and to the edge
// split points.
inline constexpr size_t kCloughTocherSplitPoints = 6, kPowellSabinSplitPoints = 12;
void writeSplitLines(const CloughTocherPatch& patch, glm::vec3* out);
void writeSplitLines(const PowellSabinPatch& patch, glm::vec3* out);
template <typename Patch>
std::vector<glm::vec3> splitLines(const std::vector<Patch>& patches, size_t pointsPerPatch) {
  std::vector<glm::vec3> out(pointsPerPatch * patches.size());
  for (size_t p = 0; p < patches.size(); ++p) writeSplitLines(patches[p], &out[pointsPerPatch * p]);
  return out;
}
std::vector<BezierVertex> powellSabinVertices(const std::vector<PowellSabinPatch>& patches);

// The control net of the radiosity surface (fig. 9.13), two points per segment. The surface
// lifts each point of a piece off its plane by heightScale * luminance(B); since that height is
// a linear function of B, its Bezier control points are the domain points (i V_0 + j V_1 +
// k V_2) / n lifted by heightScale * luminance(b_ijk), exactly. Each control point is joined
// to its neighbours b_(i-1)(j+1)k, b_(i-1)j(k+1) and b_i(j-1)(k+1), as the book draws the net.
std::vector<glm::vec3> controlNetLines(const std::vector<BezierVertex>& vertices, int degree, double heightScale);

}  // namespace radview::gl
