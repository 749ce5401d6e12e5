#pragma once
// How finely to tessellate a Bezier piece so that drawing it as linearly interpolated
// triangles (C&W §9.2: "recursively tessellating ... until some flatness
// criterion is fulfilled") stays within a tolerance of the exact piece on the display.
//
// The bound. In barycentric coordinates a degree-n piece has second derivatives along the
// direction e_i - e_j equal to n (n-1) sum_a B^{n-2}_a(beta) D2_ij b_a, with the second
// differences D2_ij b_a = b_{a+2e_i} - 2 b_{a+e_i+e_j} + b_{a+2e_j}; so they are at most
// n (n-1) M, M the largest |second difference| of the net. Uniform tessellation at level L
// makes sub-triangles whose edges are these directions scaled by 1/L. Linear interpolation on
// a triangle misses a function with bounded second derivatives by at most
// (1/2) max_point sum_{k<l} lambda_k lambda_l |D2 along edge kl| <= (1/2)(1/3) n (n-1) M / L^2
// (the weights' sum peaks at the centroid, 1/3); on an edge, a 1D curve, by (1/8) n (n-1) M_e
// / L^2 with M_e from the edge's own controls. Exact for quadratic pieces; for cubics the
// second derivative varies and the bound holds to first order.
// OpenGL's equal-spacing pattern is not that uniform split but concentric rings, whose
// triangles have edges up to ~1.15/L long and not along the edge directions, where the
// second derivative reaches ~2.2 n (n-1) M (measured): (1.15^2 x 2.2) ~ 2.9 times the
// uniform figure. The interior level therefore uses n (n-1) M / (2 L^2), three times it.
// The outer level of an edge shared by two pieces is the larger of their interior levels (and
// of the edge's own need), computed once for both (tessellationLevelsForPieces), so strip
// triangles along an edge are no coarser than the interior and neighbours agree exactly.
//
// The display. B is scaled by the exposure s and sent through the sRGB curve, whose slope is
// at most 12.92 and falls as the value rises: the error on screen is at most the error in B
// times s times the slope at the piece's darkest value (its controls bound it: a Bezier piece
// lies in the hull of its net), and zero once that is saturated (s min b >= 1).
//
// The level is the smallest L with that display error <= tolerance, clamped to 1..64.
#include "core/limits.h"
#include "core/types.h"

#include <array>
#include <vector>

namespace radview {

struct TessellationLevels {
  std::array<int, 3> outer{1, 1, 1};  // OpenGL's order: outer[i] is the edge opposite corner i
  int inner = 1;
};

// `net`: the (n+1)(n+2)/2 control values in bezierIndex order (n = 1, 2 or 3).
TessellationLevels adaptiveTessellationLevels(int degree, const Rgb* net, double exposureScale, double tolerance);

// The levels of every piece of a set that tile surfaces (3 corners each, pieces sharing an
// edge share its corner positions): each piece's own, with every shared edge's outer level
// raised to the larger need of the pieces on its two sides, so both tessellate it alike.
// `nets[p]` points at piece p's control values.
std::vector<TessellationLevels> tessellationLevelsForPieces(int degree, const std::vector<std::array<Vec3, 3>>& corners,
                                                            const std::vector<const Rgb*>& nets, double exposureScale,
                                                            double tolerance);

}  // namespace radview
