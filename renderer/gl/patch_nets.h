#pragma once
// The C1 interpolants as the deferred per-pixel pass reads them (gl/deferred_pass.h): each
// element triangle once, its three corners for the visibility raster, and its pieces'
// control values with what picks the piece, packed for a buffer the resolve shader indexes by
// triangle. The same numbers the CPU evaluates (c1_patches.h), rounded to float once. A
// piece's net is packed as lib/bezier.glsl reads it, its b_ijk (bezierIndex order) three
// floats each into vec4s, so that the shader reads whole vec4s: on llvmpipe each read is a
// gather per pixel, and reading the 30 floats of a cubic net one by one cost 2.5 times what
// reading its 8 vec4 does. No OpenGL here.
#include "interp/c1_patches.h"

#include <glm/glm.hpp>

namespace radview::gl {

// Clough-Tocher: piece k's net in vec4 8 k .. 8 k + 7.
inline constexpr size_t kCloughTocherVec4s = 24;
// Powell-Sabin: piece p's six b_ijk in vec4 5 p .. 5 p + 4, then (zeta, 0) (the incenter's
// barycentric coordinates) and (t, 0) (the edge split parameters).
inline constexpr size_t kPowellSabinVec4s = 32;

// The vec4s per triangle of the pieces of `degree`: 3 Clough-Tocher, 2 Powell-Sabin.
constexpr size_t netVec4s(int degree) { return degree == 3 ? kCloughTocherVec4s : kPowellSabinVec4s; }

// Writes the patch's corners (3) and net (netVec4s).
void writeNet(const CloughTocherPatch& patch, glm::vec3* corners, glm::vec4* net);
void writeNet(const PowellSabinPatch& patch, glm::vec3* corners, glm::vec4* net);

}  // namespace radview::gl
