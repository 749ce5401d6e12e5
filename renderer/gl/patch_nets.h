#pragma once
// The C1 interpolants as the deferred per-pixel pass reads them (gl/deferred_pass.h): each
// element triangle once, its three corners for the visibility raster, and its pieces'
// control values with what picks the piece, packed as floats for a storage buffer the
// resolve shader indexes by triangle. The same numbers the CPU evaluates (c1_patches.h),
// rounded to float once. No OpenGL here.
#include "interp/c1_patches.h"

#include <glm/glm.hpp>

#include <vector>

namespace radview::gl {

// A piece's net is packed as lib/bezier.glsl reads it, its b_ijk (bezierIndex order) three
// floats each into vec4s, so that the shader reads whole vec4s: on llvmpipe each storage-buffer
// read is a gather per pixel, and reading the 30 floats of a cubic net one by one cost 2.5
// times what reading its 8 vec4 does.
struct PatchNets {
  int degree = 3;                  // of the pieces: 3 Clough-Tocher, 2 Powell-Sabin
  std::vector<glm::vec3> corners;  // V0 V1 V2 of each triangle, in the GPU's frame
  std::vector<glm::vec4> nets;     // per triangle, the layouts below
  size_t triangles() const { return corners.size() / 3; }
};

// Clough-Tocher: piece k's net in vec4 8 k .. 8 k + 7.
inline constexpr size_t kCloughTocherVec4s = 24;
// Powell-Sabin: piece p's six b_ijk in vec4 5 p .. 5 p + 4, then (zeta, 0) (the incenter's
// barycentric coordinates) and (t, 0) (the edge split parameters).
inline constexpr size_t kPowellSabinVec4s = 32;

PatchNets cloughTocherNets(const std::vector<CloughTocherPatch>& patches);
PatchNets powellSabinNets(const std::vector<PowellSabinPatch>& patches);

}  // namespace radview::gl
