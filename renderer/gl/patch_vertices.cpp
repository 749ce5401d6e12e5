#include "gl/patch_vertices.h"

#include "mesh/display_mesh.h"

#include <cmath>

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

// The same piece with its first two corners swapped, so that it turns the other way: the net
// re-indexed b_ijk -> b_jik. Powell-Sabin's pieces alternate in orientation; the radiosity
// surface lifts each piece along its corners' right-hand normal, so every piece must turn
// the way its element does.
template <size_t N>
void addPieceReversed(std::vector<BezierVertex>& out, const std::array<Vec3, 3>& corners, const std::array<Rgb, N>& b) {
  const int n = N == 10 ? 3 : 2;
  std::array<Rgb, N> swapped{};
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) swapped[bezierIndex(n, j, i)] = b[bezierIndex(n, i, j)];
  addPiece(out, {corners[1], corners[0], corners[2]}, swapped);
}

void addQuadraticTriangle(std::vector<BezierVertex>& out, const RadiosityMesh& mesh, const Element& element) {
  const auto& c = element.corners;
  const auto& m = element.midEdge;  // m[i] on edge c[i] -> c[i+1]
  auto B = [&](uint32_t n) { return mesh.nodes[n].B; };
  const Rgb f0 = B(c[0]), f1 = B(c[1]), f2 = B(c[2]);
  // bezierIndex order for n = 2: b200 b110 b101 b020 b011 b002.
  const std::array<Rgb, 6> net = {f0, 2.0 * B(m[0]) - 0.5 * (f0 + f1), 2.0 * B(m[2]) - 0.5 * (f0 + f2),
                                  f1, 2.0 * B(m[1]) - 0.5 * (f1 + f2), f2};
  addPiece(out, {mesh.nodes[c[0]].position, mesh.nodes[c[1]].position, mesh.nodes[c[2]].position}, net);
}

}  // namespace

std::vector<BezierVertex> quadraticTriangleVertices(const RadiosityMesh& mesh) {
  std::vector<BezierVertex> out;
  for (const Element& element : mesh.elements)
    if (isQuadraticTriangle(element)) addQuadraticTriangle(out, mesh, element);
  return out;
}

std::vector<BezierVertex> quadraticLagrangeVertices(const RadiosityMesh& mesh, const MeshTopology& topology,
                                                    size_t* serendipityStart) {
  std::vector<BezierVertex> out;
  auto position = [&](uint32_t n) { return mesh.nodes[n].position; };
  std::vector<size_t> serendipity;
  const std::vector<std::vector<TVertex>> tVertices = tVerticesByElement(mesh, topology);
  // A linear piece over each drawn triangle, T-vertices included (watertightTriangles).
  auto addLinear = [&](size_t e) {
    for (const auto& t : watertightTriangles(mesh, e, tVertices[e]))
      addPiece(out, {position(t[0].node), position(t[1].node), position(t[2].node)},
               linearBezierNet<6>({t[0].B, t[1].B, t[2].B}));
  };
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& element = mesh.elements[e];
    if (isSerendipityQuad(mesh, e)) {
      serendipity.push_back(e);
      continue;
    }
    if (isQuadraticTriangle(element)) {
      addQuadraticTriangle(out, mesh, element);
      continue;
    }
    addLinear(e);
  }
  if (serendipityStart) *serendipityStart = out.size() / 3;
  for (size_t e : serendipity) addLinear(e);
  return out;
}

std::vector<BezierVertex> cloughTocherVertices(const std::vector<CloughTocherPatch>& patches) {
  std::vector<BezierVertex> out;
  out.reserve(patches.size() * 9);
  for (const CloughTocherPatch& p : patches)
    for (int k = 0; k < 3; ++k)  // piece k: (V_k, V_k+1, C)
      addPiece(out, {p.frame.V[k], p.frame.V[(k + 1) % 3], p.C}, p.control[k]);
  return out;
}

void writeSplitLines(const CloughTocherPatch& patch, glm::vec3* out) {
  for (const Vec3& V : patch.frame.V) {
    *out++ = glm::vec3(V);
    *out++ = glm::vec3(patch.C);
  }
}

void writeSplitLines(const PowellSabinPatch& patch, glm::vec3* out) {
  for (int k = 0; k < 3; ++k) {
    const Vec3 &a = patch.frame.V[k], &b = patch.frame.V[(k + 1) % 3];
    for (const Vec3& end : {a, (1.0 - patch.t[k]) * a + patch.t[k] * b}) {
      *out++ = glm::vec3(patch.Z);
      *out++ = glm::vec3(end);
    }
  }
}

std::vector<BezierVertex> powellSabinVertices(const std::vector<PowellSabinPatch>& patches) {
  std::vector<BezierVertex> out;
  out.reserve(patches.size() * 18);
  for (const PowellSabinPatch& p : patches)
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = p.frame.V[k], &b = p.frame.V[(k + 1) % 3];
      const Vec3 R = (1.0 - p.t[k]) * a + p.t[k] * b;
      addPiece(out, {a, R, p.Z}, p.control[2 * k]);              // piece 2k: (V_k, R_k, Z)
      addPieceReversed(out, {b, R, p.Z}, p.control[2 * k + 1]);  // piece 2k+1: (V_k+1, R_k, Z)
    }
  return out;
}

std::vector<glm::vec3> controlNetLines(const std::vector<BezierVertex>& vertices, int degree, double heightScale) {
  std::vector<glm::vec3> out;
  const int n = degree;
  const int count = (n + 1) * (n + 2) / 2;
  const glm::vec3 luminanceWeights(0.2126f, 0.7152f, 0.0722f);
  auto indexOf = [n](int i, int j) { return bezierIndex(n, i, j); };
  std::vector<glm::vec3> lifted(count);
  for (size_t first = 0; first + 2 < vertices.size(); first += 3) {
    const glm::vec3 V0 = vertices[first].position, V1 = vertices[first + 1].position, V2 = vertices[first + 2].position;
    const glm::vec3 normal = glm::normalize(glm::cross(V1 - V0, V2 - V0));
    if (!std::isfinite(normal.x)) continue;  // a degenerate piece has no surface to draw
    const BezierVertex& piece = vertices[first];
    for (int i = n; i >= 0; --i)
      for (int j = n - i; j >= 0; --j) {
        const int k = n - i - j, index = indexOf(i, j);
        const int f = 3 * index;
        const glm::vec3 b(piece.control[f / 4][f % 4], piece.control[(f + 1) / 4][(f + 1) % 4],
                          piece.control[(f + 2) / 4][(f + 2) % 4]);
        const glm::vec3 domain = (float(i) * V0 + float(j) * V1 + float(k) * V2) / float(n);
        lifted[index] = domain + normal * float(heightScale * glm::dot(b, luminanceWeights));
      }
    for (int i = n; i >= 0; --i)
      for (int j = n - i; j >= 0; --j) {
        const glm::vec3 p = lifted[indexOf(i, j)];
        if (i > 0) {
          for (const glm::vec3& q : {lifted[indexOf(i - 1, j + 1)], lifted[indexOf(i - 1, j)]}) {
            out.push_back(p);
            out.push_back(q);
          }
        }
        if (j > 0) {
          out.push_back(p);
          out.push_back(lifted[indexOf(i, j - 1)]);
        }
      }
  }
  return out;
}

}  // namespace radview::gl
