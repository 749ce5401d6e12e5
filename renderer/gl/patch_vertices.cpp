#include "gl/patch_vertices.h"

namespace radview::gl {

namespace {

template <size_t N>
void addPiece(std::vector<BezierVertex>& out, const std::array<Vec3, 3>& corners, const std::array<Rgb, N>& b) {
  BezierVertex v{};
  for (size_t i = 0; i < N; ++i)
    for (int c = 0; c < 3; ++c) v.control[(3 * i + c) / 4][(3 * i + c) % 4] = float(b[i][c]);
  const glm::vec3 betas[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int k = 0; k < 3; ++k) {
    v.position = glm::vec3(corners[k]);
    v.beta = betas[k];
    out.push_back(v);
  }
}

}  // namespace

std::vector<BezierVertex> cloughTocherVertices(const std::vector<CloughTocherPatch>& patches) {
  std::vector<BezierVertex> out;
  out.reserve(patches.size() * 9);
  for (const CloughTocherPatch& p : patches)
    for (int k = 0; k < 3; ++k)  // piece k: (V_k, V_k+1, C)
      addPiece(out, {p.frame.V[k], p.frame.V[(k + 1) % 3], p.C}, p.control[k]);
  return out;
}

std::vector<BezierVertex> powellSabinVertices(const std::vector<PowellSabinPatch>& patches) {
  std::vector<BezierVertex> out;
  out.reserve(patches.size() * 18);
  for (const PowellSabinPatch& p : patches)
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = p.frame.V[k], &b = p.frame.V[(k + 1) % 3];
      const Vec3 R = (1.0 - p.t[k]) * a + p.t[k] * b;
      addPiece(out, {a, R, p.Z}, p.control[2 * k]);      // piece 2k: (V_k, R_k, Z)
      addPiece(out, {b, R, p.Z}, p.control[2 * k + 1]);  // piece 2k+1: (V_k+1, R_k, Z)
    }
  return out;
}

}  // namespace radview::gl
