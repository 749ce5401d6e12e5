#pragma once
// The C1 interpolants as the deferred per-pixel pass reads them (gl/deferred_pass.h): each
// element triangle once, its three corners for the visibility raster, and what determines its
// pieces, packed for a buffer the resolve shader indexes by triangle. Not the pieces' whole
// nets: the control values the C1 conditions inside the triangle fix are left for the shader
// to form (C&W §9.2.2, fig. 9.12 step 4; the Powell-Sabin split's mid values), which keeps a
// triangle to 144 bytes where its nets take 384 (Clough-Tocher) or 512 (Powell-Sabin). The
// same numbers the CPU evaluates (c1_patches.h), rounded to float once; the shader reads whole
// vec4s, as on llvmpipe each read is a gather per pixel. No OpenGL here.
#include "interp/c1_patches.h"

#include <glm/glm.hpp>

namespace radview::gl {

// Both C1 methods pack 12 RGB values, three floats each, and what picks the piece into 9 vec4.
// Clough-Tocher: the corner values f_i (values 0-2), then per outer edge k = (V_k, V_k+1) the
// tangent-plane values next to either end, b210 and b120 of piece k (values 3 + 2 k, 4 + 2 k),
// then each piece's b111 (9 + k).
// Powell-Sabin: vec4 i = (f_i, zeta_i); 3 + k = (D_k, t_k); 6 + k = (E_k, 0), with zeta the
// split point's barycentric coordinates, t_k the edge split parameters, and D_k, E_k the
// derivatives of B along edge k from either end, grad f_k . (V_k+1 - V_k) and
// grad f_k+1 . (V_k - V_k+1): every control value is f plus a multiple of them (C&W fig. 9.9).
inline constexpr size_t kNetVec4s = 9;

// Writes the patch's corners (3) and its packed values (kNetVec4s).
void writeNet(const CloughTocherPatch& patch, glm::vec3* corners, glm::vec4* net);
void writeNet(const PowellSabinPatch& patch, glm::vec3* corners, glm::vec4* net);

}  // namespace radview::gl
