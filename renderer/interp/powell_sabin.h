#pragma once
// The Powell-Sabin element on one triangle, Reichert's C1 quadratic interpolant (C&W §9.2.2,
// fig. 9.9; Powell & Sabin 1977): the triangle split six ways, at its incenter Z and at one
// point R_k on each edge, into quadratic Bezier pieces built from the corner values f and
// surface gradients g. Neighbours join C1 across an edge when both use the same R there, on
// the segment between their incenters (edgeSplitPoint), and the same gradients at its ends.
#include "interp/bezier_triangle.h"

#include <array>

namespace radview {

// The incenter (the center of the inscribed circle): sum_i |opposite side_i| V_i / perimeter.
// All three vertices coincident: that point.
Vec3 incenter(const Vec3& V0, const Vec3& V1, const Vec3& V2);

// R on the edge Vi - Vj for the triangle with incenter Z and its neighbour across the edge
// with incenter Zneighbour: where the segment Z - Zneighbour crosses the edge, the two
// triangles unfolded into one plane about the edge (so it is defined for 3D neighbours too).
// Computed without intersecting lines: Z is at distance r (its inradius) from the edge with
// its foot, the incircle's touch point, at edge parameter tZ (likewise r', tZ'), so the
// crossing is at t = (r' tZ + r tZ') / (r + r'): a convex combination of two touch points,
// always on the edge, and accurate however flat the angle between the segment and the edge
// (small r + r'). Both triangles degenerate (r + r' = 0): the midpoint. Symmetric, to the
// last bit, in swapping (Vi, Vj) and (Z, Zneighbour), so both neighbours get the same R.
// A boundary edge has no neighbour: use its midpoint.
Vec3 edgeSplitPoint(const Vec3& Vi, const Vec3& Vj, const Vec3& Z, const Vec3& Zneighbour);

struct PowellSabinPatch {
  BarycentricFrame frame;     // of V0 V1 V2
  Vec3 Z{0.0};                // the incenter (the centroid of a degenerate triangle)
  Vec3 zeta{0.0};             // Z = sum_i zeta_i V_i
  std::array<double, 3> t{};  // R_k = (1 - t_k) V_k + t_k V_k+1, 0 < t_k < 1
  // Piece 2k is the sub-triangle (V_k, R_k, Z), piece 2k+1 is (V_k+1, R_k, Z); their b_ijk
  // (order of bezierIndex) have i for the vertex, j for R_k and k for Z.
  std::array<std::array<Rgb, 6>, 6> control{};
};

// The control values (see the .cpp for why each is what it is). g[i][c] is the gradient of
// channel c at corner i, in the triangle's plane. R[k] is the split point of edge k
// (V_k -> V_k+1); it is projected onto the edge and kept 1e-9 of the edge inside its ends.
// Reproduces every quadratic given its exact gradients. A degenerate triangle (see
// BarycentricFrame) gets the linear interpolant of f, zero gradient. Preconditions
// (checked): finite input.
PowellSabinPatch buildPowellSabin(const std::array<Vec3, 3>& V, const std::array<Rgb, 3>& f,
                                  const std::array<RgbGradient, 3>& g, const std::array<Vec3, 3>& R);

// B and its world gradient at barycentric coordinates lambda of the big triangle, from the
// piece that contains the point (on an inner edge either; they agree).
Sample evaluate(const PowellSabinPatch& patch, const Vec3& lambda);
// Piece p's polynomial (0..5, as in PowellSabinPatch), extended beyond the piece, at lambda.
Sample evaluatePiece(const PowellSabinPatch& patch, int piece, const Vec3& lambda);

}  // namespace radview
