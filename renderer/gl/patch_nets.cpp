#include "gl/patch_nets.h"

namespace radview::gl {

namespace {

template <typename Patch>
void addCorners(PatchNets& out, const Patch& p) {
  for (const Vec3& V : p.frame.V) out.corners.push_back(glm::vec3(V));
}

// The net in `vec4s` vec4 (zero after its values).
template <size_t N>
void addNet(PatchNets& out, const std::array<Rgb, N>& b, size_t vec4s) {
  const size_t first = out.nets.size();
  out.nets.resize(first + vec4s, glm::vec4(0.0f));
  for (size_t i = 0; i < N; ++i)
    for (size_t c = 0; c < 3; ++c) out.nets[first + (3 * i + c) / 4][(3 * i + c) % 4] = float(b[i][c]);
}

}  // namespace

PatchNets cloughTocherNets(const std::vector<CloughTocherPatch>& patches) {
  PatchNets out;
  out.degree = 3;
  out.corners.reserve(3 * patches.size());
  out.nets.reserve(kCloughTocherVec4s * patches.size());
  for (const CloughTocherPatch& p : patches) {
    addCorners(out, p);
    for (const auto& piece : p.control) addNet(out, piece, 8);
  }
  return out;
}

PatchNets powellSabinNets(const std::vector<PowellSabinPatch>& patches) {
  PatchNets out;
  out.degree = 2;
  out.corners.reserve(3 * patches.size());
  out.nets.reserve(kPowellSabinVec4s * patches.size());
  for (const PowellSabinPatch& p : patches) {
    addCorners(out, p);
    for (const auto& piece : p.control) addNet(out, piece, 5);
    out.nets.push_back(glm::vec4(glm::vec3(p.zeta), 0.0f));
    out.nets.push_back(glm::vec4(float(p.t[0]), float(p.t[1]), float(p.t[2]), 0.0f));
  }
  return out;
}

}  // namespace radview::gl
