#include "scene/quad_merge.h"

#include "geom/polygon.h"
#include "geom/weld.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>

namespace radview {

namespace {

constexpr uint32_t kNone = UINT32_MAX;

// A triangle's preferred partner: triangle `partner`, across the triangle's edge `edge` and the
// partner's edge `partnerEdge`, of the given length.
struct Match {
  uint32_t partner = kNone;
  int edge = 0, partnerEdge = 0;
  double length = -1.0;
};

class QuadMerger {
 public:
  QuadMerger(const Scene& scene, double relativeTolerance) : scene_(scene), tolerance_(relativeTolerance) {
    for (uint32_t p = 0; p < scene.polygons.size(); ++p)
      if (scene.polygons[p].vertices.size() == 3) triangles_.push_back(p);
    weldCorners();
  }

  Scene merge() {
    const std::vector<Match> preferred = preferredPartners();
    Scene out = scene_;
    out.polygons.clear();
    size_t next = 0;  // the next triangle, in polygon order
    for (uint32_t p = 0; p < scene_.polygons.size(); ++p) {
      if (next == triangles_.size() || triangles_[next] != p) {
        out.polygons.push_back(scene_.polygons[p]);
        continue;
      }
      const uint32_t t = uint32_t(next++);
      const Match& m = preferred[t];
      if (m.partner == kNone || preferred[m.partner].partner != t) {
        out.polygons.push_back(scene_.polygons[p]);
      } else if (t < m.partner) {
        Polygon quad = scene_.polygons[p];
        quad.vertices = quadCorners(t, m.edge, m.partner, m.partnerEdge);
        // quadCorners starts at t's corner k; t's corner 0 is at index 0, 3, 2 for k = 0, 1, 2.
        std::rotate(quad.vertices.begin(), quad.vertices.begin() + std::array<int, 3>{0, 3, 2}[m.edge],
                    quad.vertices.end());
        out.polygons.push_back(quad);
      }
    }
    return out;
  }

 private:
  const Scene& scene_;
  const double tolerance_;
  std::vector<uint32_t> triangles_;                // polygon index of each triangle
  std::vector<std::array<uint32_t, 3>> cornerId_;  // welded position id of each triangle corner

  const std::vector<Vec3>& corners(uint32_t t) const { return scene_.polygons[triangles_[t]].vertices; }

  void weldCorners() {
    std::vector<Vec3> points;
    for (uint32_t t = 0; t < triangles_.size(); ++t) points.insert(points.end(), corners(t).begin(), corners(t).end());
    const WeldedPoints welded = weldPoints(points, tolerance_ * scene_.bounds().diagonal());
    for (uint32_t t = 0; t < triangles_.size(); ++t)
      cornerId_.push_back({welded.id[3 * t], welded.id[3 * t + 1], welded.id[3 * t + 2]});
  }

  // Rules 1-4 for triangle t across its edge k and triangle u across its edge ku.
  bool canMerge(uint32_t t, int k, uint32_t u, int ku) const {
    const auto &T = cornerId_[t], &U = cornerId_[u];
    if (U[ku] != T[(k + 1) % 3] || U[(ku + 1) % 3] != T[k]) return false;  // same direction: folded
    if (scene_.polygons[triangles_[t]].material != scene_.polygons[triangles_[u]].material) return false;
    const Vec3 c = corners(t)[(k + 2) % 3], d = corners(u)[(ku + 2) % 3];
    const Vec3 nT = unitNormal(corners(t)), nU = unitNormal(corners(u));
    if (nT == Vec3(0.0) || nU == Vec3(0.0)) return false;
    const double size = std::max(glm::distance(corners(t)[k], corners(t)[(k + 1) % 3]), glm::distance(c, d));
    if (std::abs(glm::dot(d - corners(t)[k], nT)) > tolerance_ * size) return false;
    if (std::abs(glm::dot(c - corners(u)[ku], nU)) > tolerance_ * size) return false;
    return isStrictlyConvex(quadCorners(t, k, u, ku));
  }

  // t = (a, b, c) with edge k = a -> b, and u's far vertex d: the quad a, d, b, c.
  std::vector<Vec3> quadCorners(uint32_t t, int k, uint32_t u, int ku) const {
    return {corners(t)[k], corners(u)[(ku + 2) % 3], corners(t)[(k + 1) % 3], corners(t)[(k + 2) % 3]};
  }

  // Rule 5: for every triangle, the mergeable neighbour across its longest edge.
  std::vector<Match> preferredPartners() const {
    // Triangle edges keyed by their (unordered) end ids; an edge with exactly two triangles on it
    // is a candidate (more would be a non-manifold fin: left alone).
    std::vector<std::tuple<uint64_t, uint32_t, int>> edges;
    for (uint32_t t = 0; t < triangles_.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = cornerId_[t][k], b = cornerId_[t][(k + 1) % 3];
        if (a != b) edges.emplace_back(uint64_t(std::min(a, b)) << 32 | std::max(a, b), t, k);
      }
    std::sort(edges.begin(), edges.end());
    std::vector<Match> preferred(triangles_.size());
    auto consider = [&](uint32_t t, int k, uint32_t u, int ku) {
      if (!canMerge(t, k, u, ku)) return;
      const double length = glm::distance(corners(t)[k], corners(t)[(k + 1) % 3]);
      Match& best = preferred[t];
      if (length > best.length || (length == best.length && u < best.partner)) best = {u, k, ku, length};
    };
    for (size_t i = 0; i < edges.size();) {
      size_t end = i;
      while (end < edges.size() && std::get<0>(edges[end]) == std::get<0>(edges[i])) ++end;
      if (end - i == 2) {
        const auto [key0, t, k] = edges[i];
        const auto [key1, u, ku] = edges[i + 1];
        if (t != u) {
          consider(t, k, u, ku);
          consider(u, ku, t, k);
        }
      }
      i = end;
    }
    return preferred;
  }
};

}  // namespace

Scene mergeTrianglesIntoQuads(const Scene& scene, double relativeTolerance) {
  return QuadMerger(scene, relativeTolerance).merge();
}

}  // namespace radview
