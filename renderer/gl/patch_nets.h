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
// P the polynomial of the piece where lambda_0 is the smallest, values 0-9 its Bezier net in
// lambda (order of bezierIndex) times the Bernstein weights 3!/(i! j! k!), alpha and beta
// values 10 and 11. psi vanishes where lambda_0
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
