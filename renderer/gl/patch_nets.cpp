#include "gl/patch_nets.h"

#include "interp/bezier_triangle.h"

namespace radview::gl {

namespace {

template <typename Patch>
void writeCorners(const Patch& patch, glm::vec3* corners) {
  for (int k = 0; k < 3; ++k) corners[k] = glm::vec3(patch.frame.V[k]);
}

// RGB value `i` into floats 3 i .. 3 i + 2 of the vec4s.
void pack(glm::vec4* out, size_t i, const Rgb& value) {
  for (size_t c = 0; c < 3; ++c) out[(3 * i + c) / 4][(3 * i + c) % 4] = float(value[c]);
}

glm::vec4 withW(const Rgb& value, double w) { return glm::vec4(glm::vec3(value), float(w)); }

}  // namespace

void writeNet(const CloughTocherPatch& patch, glm::vec3* corners, glm::vec4* net) {
  writeCorners(patch, corners);
  for (size_t i = 0; i < kNetVec4s; ++i) net[i] = glm::vec4(0.0f);
  for (int k = 0; k < 3; ++k) {
    const auto& b = patch.control[k];
    pack(net, size_t(k), b[bezierIndex(3, 3, 0)]);
    pack(net, size_t(3 + 2 * k), b[bezierIndex(3, 2, 1)]);
    pack(net, size_t(4 + 2 * k), b[bezierIndex(3, 1, 2)]);
    pack(net, size_t(9 + k), b[bezierIndex(3, 1, 1)]);
  }
}

void writeNet(const PowellSabinPatch& patch, glm::vec3* corners, glm::vec4* net) {
  writeCorners(patch, corners);
  // Piece 2 k is (f_k, bVR_k, ...) and 2 k + 1 (f_k+1, bV1R_k, ...), b200 b110 first; bVR_k =
  // f_k + t_k D_k / 2 and bV1R_k = f_k+1 + (1 - t_k) E_k / 2 (powell_sabin.cpp), so D and E
  // come back from them exactly but for rounding, also where a degenerate triangle is linear.
  for (int k = 0; k < 3; ++k) {
    const auto &near = patch.control[2 * k], &far = patch.control[2 * k + 1];
    const double t = patch.t[k];
    net[k] = withW(near[0], patch.zeta[k]);
    net[3 + k] = withW(2.0 * (near[1] - near[0]) / t, t);
    net[6 + k] = withW(2.0 * (far[1] - far[0]) / (1.0 - t), 0.0);
  }
}

}  // namespace radview::gl
