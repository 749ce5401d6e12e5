#pragma once
// The Clough-Tocher element on one triangle (C&W §9.2.2, figs. 9.11-9.12; Salesin et al.
// 1992): the triangle split at its centroid C into three cubic Bezier pieces, built from the
// values f and surface gradients g at its corners and a cross-boundary condition per edge.
// Pure per-triangle mathematics: the mesh layer chooses g (per corner, so a C0 vertex can
// give each triangle its own) and the conditions that make neighbours join C1.
#include "interp/bezier_triangle.h"

#include <array>
#include <optional>

namespace radview {

// The condition across outer edge k (V_k -> V_k+1), C&W step 3 (the wedge of the two b on
// the edge and the c on each side).
struct CrossBoundary {
  // Direction across the edge (its component off the triangle's plane is ignored); must not be
  // parallel to the edge: within 1e-10 rad of it (or zero) the edge's unit normal is used
  // instead, midDerivative then read along that.
  Vec3 d{0.0};
  // Reduced element: the derivative along d varies linearly along the edge, between the end
  // values dot(g_k, d) and dot(g_k+1, d) (the wedge's slope across the edge is the average of
  // the two corners'). Two triangles that share the edge, its end gradients and d (up to
  // sign) then join C1 across it. Otherwise the full Clough-Tocher element: the derivative
  // along d is quadratic along the edge with midDerivative at the midpoint.
  bool reduced = true;
  Rgb midDerivative{0.0};  // full element only: dot(grad f, d) at the edge midpoint, per channel
};

struct CloughTocherPatch {
  BarycentricFrame frame;  // of V0 V1 V2
  Vec3 C{0.0};             // centroid
  // Piece k is the sub-triangle (V_k, V_k+1, C); its b_ijk (order of bezierIndex) have i for
  // V_k, j for V_k+1 and k for C. In fig. 9.12's letters: a = b300, b030; b = b210, b120 (outer
  // edge), b201, b021 (inner edges); c = b111; d = b102, b012; e = b003.
  std::array<std::array<Rgb, 10>, 3> control{};
};

// Steps a-e of fig. 9.12 (see the .cpp). g[i][c] is the gradient of channel c at corner i, in
// the triangle's plane (an off-plane component is ignored). Reproduces every quadratic given
// its exact gradients, for any d; the full element reproduces cubics given exact mid-edge
// derivatives. A degenerate triangle (see BarycentricFrame) gets the linear interpolant of f
// in the barycentric coordinates it is evaluated at, with zero gradient. Preconditions
// (checked): finite input.
CloughTocherPatch buildCloughTocher(const std::array<Vec3, 3>& V, const std::array<Rgb, 3>& f,
                                    const std::array<RgbGradient, 3>& g, const std::array<CrossBoundary, 3>& edges);

// B and its world gradient at barycentric coordinates lambda of the big triangle, from the
// piece that contains the point (on an inner edge either piece; they agree). Points slightly
// outside are extrapolated from the piece of the nearest outer edge.
Sample evaluate(const CloughTocherPatch& patch, const Vec3& lambda);
// Piece k's polynomial, extended beyond the piece, at lambda (what evaluate uses inside it).
Sample evaluatePiece(const CloughTocherPatch& patch, int k, const Vec3& lambda);

// The two standard choices of d_k.
// The book's: the edge's unit normal in the plane of (V_k, V_k1, C), pointing into the
// triangle (C&W step 3 reads the wedge's normal as the edge normal). Not affine invariant:
// it amplifies values on needle triangles.
Vec3 bookCrossDirection(const Vec3& V_k, const Vec3& V_k1, const Vec3& C);
// The affine-invariant one of scipy's CloughTocher2DInterpolator: neighbourC - C across an
// interior edge, C - (V_k + V_k1) / 2 across a boundary edge (no neighbour).
Vec3 affineCrossDirection(const Vec3& V_k, const Vec3& V_k1, const Vec3& C, const std::optional<Vec3>& neighbourC);

}  // namespace radview
