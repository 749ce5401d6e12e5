#pragma once
// The C1 interpolants as the per-pixel passes read them (gl/deferred_pass.h): each element
// triangle once, its three corners for the raster, and its pieces in 36 floats, 12 per corner,
// packed for a buffer read per pixel by triangle or per vertex by corner. A triangle takes 144
// bytes where the pieces' nets take 384 (Clough-Tocher) or 512 (Powell-Sabin). Computed in
// double from the patches the CPU evaluates (c1_patches.h) and rounded to float once; the
// shaders read whole vec4s, as on llvmpipe each read is a gather. No OpenGL here.
#include "interp/c1_patches.h"

#include <glm/glm.hpp>

namespace radview::gl {

// Both C1 methods pack 12 floats per corner of each triangle, 9 vec4 in all.
// Clough-Tocher: the split at the centroid is the same in every triangle's barycentric
// coordinates, so the C1 piecewise cubics on it are the cubics plus two fixed functions
// (a cubic's 10 values, the element's 12):
//   B(lambda) = P(lambda) + alpha psi_1(lambda) + beta psi_2(lambda),
// P the polynomial of the piece where lambda_0 is the smallest, its Bezier net in lambda times
// the Bernstein weights 3!/(i! j! k!), p_ijk for the monomial u^i v^j w^k, (u, v, w) = lambda.
// The values are grouped by corner, four each, so that each vertex of the one-pass draw reads
// only its own (c1_forward.vert): corner k holds values whose monomial has a factor lambda_k,
// one for each of the monomials u^2, v^2, w^2, u w that is left when lambda_k is taken out
// (0 where none is), and P = S_uu u^2 + S_vv v^2 + S_ww w^2 + S_uw u w with S the corners'
// values interpolated linearly:
//   corner 0: p300, p120, p102, p201;  corner 1: p210, p030, p012, p111;
//   corner 2: alpha, p021, p003, beta  (its u^2 and u w values are 0). psi vanishes where lambda_0
// is the smallest; where lambda_1 is, psi_1 = (lambda_1 - lambda_0)^2 (lambda_0 + lambda_1 -
// 2 lambda_2) and psi_2 = (lambda_1 - lambda_0)^2 (lambda_2 - lambda_0); where lambda_2 is,
// psi_1 = (lambda_2 - lambda_0)^2 (lambda_0 - lambda_1) and psi_2 = (lambda_2 - lambda_0)^2
// (2 lambda_1 - lambda_0 - lambda_2). Each joins its neighbours C1 across the inner edges
// (a difference of cubics with a double zero along a line is that line squared times a linear
// function). A pixel then evaluates one cubic and a correction, not a piece chosen from three.
// Powell-Sabin: with f the corner values and D_k, E_k the derivatives of B along edge k from
// either end, grad f_k . (V_k+1 - V_k) and grad f_k+1 . (V_k - V_k+1), every control value is
// f plus a multiple of them (C&W fig. 9.9), and the spline is linear in them and reproduces
// quadratics: B = Q + R, Q the quadratic with the values f and the derivatives D, R the
// spline with f = D = 0 and E = e, e_k = E_k - D_k + 2 (f_k+1 - f_k) (Q's own E_k is
// D_k - 2 (f_k+1 - f_k)). Q = u S_u + v S_v + w S_w, each S interpolated from two corners
// (lib/c1_pieces.glsl): corner 0 holds f_0 (of S_u) and 2 f_2 + D_2 (S_w), corner 1 2 f_0 +
// D_0 (S_u) and f_1 (S_v), corner 2 2 f_1 + D_1 (S_v) and f_2 (S_w). Corner k's 12 floats are
// those two, e_k, t_k (the edge split parameter) and two more: zeta_0 and zeta_1 (the split
// point's barycentric coordinates, which sum to 1) at corner 0, zeros at the others.
inline constexpr size_t kNetVec4s = 9;

// Writes the patch's corners (3) and its packed values (kNetVec4s).
void writeNet(const CloughTocherPatch& patch, glm::vec3* corners, glm::vec4* net);
void writeNet(const PowellSabinPatch& patch, glm::vec3* corners, glm::vec4* net);

}  // namespace radview::gl
