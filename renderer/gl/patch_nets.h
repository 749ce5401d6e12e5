#pragma once
// The C1 interpolants as the per-pixel passes read them (gl/deferred_pass.h): each element
// triangle once, its three corners for the raster, and its pieces in 12 RGB values, packed for
// a buffer the shaders index by triangle. A triangle takes 144 bytes where the pieces' nets
// take 384 (Clough-Tocher) or 512 (Powell-Sabin). Computed in double from the patches the CPU
// evaluates (c1_patches.h) and rounded to float once; the shader reads whole vec4s, as on
// llvmpipe each read is a gather per pixel. No OpenGL here.
#include "interp/c1_patches.h"

#include <glm/glm.hpp>

namespace radview::gl {

// Both C1 methods pack 12 RGB values, three floats each, and what picks the piece into 9 vec4.
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
// Powell-Sabin: vec4 i = (f_i, zeta_i); 3 + k = (D_k, t_k); 6 + k = (E_k, 0), with zeta the
// split point's barycentric coordinates, t_k the edge split parameters, and D_k, E_k the
// derivatives of B along edge k from either end, grad f_k . (V_k+1 - V_k) and
// grad f_k+1 . (V_k - V_k+1): every control value is f plus a multiple of them (C&W fig. 9.9).
inline constexpr size_t kNetVec4s = 9;

// Writes the patch's corners (3) and its packed values (kNetVec4s).
void writeNet(const CloughTocherPatch& patch, glm::vec3* corners, glm::vec4* net);
void writeNet(const PowellSabinPatch& patch, glm::vec3* corners, glm::vec4* net);

}  // namespace radview::gl
