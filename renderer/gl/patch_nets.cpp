#include "gl/patch_nets.h"

namespace radview::gl {

namespace {

template <typename Patch>
void writeCorners(const Patch& patch, glm::vec3* corners) {
  for (int k = 0; k < 3; ++k) corners[k] = glm::vec3(patch.frame.V[k]);
}

// The piece's net into `vec4s` vec4, zero after its values.
template <size_t N>
void writePiece(const std::array<Rgb, N>& b, glm::vec4* out, size_t vec4s) {
  for (size_t i = 0; i < vec4s; ++i) out[i] = glm::vec4(0.0f);
  for (size_t i = 0; i < N; ++i)
    for (size_t c = 0; c < 3; ++c) out[(3 * i + c) / 4][(3 * i + c) % 4] = float(b[i][c]);
}

}  // namespace

void writeNet(const CloughTocherPatch& patch, glm::vec3* corners, glm::vec4* net) {
  writeCorners(patch, corners);
  for (int k = 0; k < 3; ++k) writePiece(patch.control[k], net + 8 * k, 8);
}

void writeNet(const PowellSabinPatch& patch, glm::vec3* corners, glm::vec4* net) {
  writeCorners(patch, corners);
  for (int p = 0; p < 6; ++p) writePiece(patch.control[p], net + 5 * p, 5);
  net[30] = glm::vec4(glm::vec3(patch.zeta), 0.0f);
  net[31] = glm::vec4(float(patch.t[0]), float(patch.t[1]), float(patch.t[2]), 0.0f);
}

}  // namespace radview::gl
