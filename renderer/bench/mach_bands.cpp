#include "bench/mach_bands.h"

#include "bench/image_error.h"
#include "core/display_transform.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace radview {

namespace {

using Point = std::array<double, 3>;
using EdgeKey = std::pair<Point, Point>;  // the two end positions, ordered

EdgeKey edgeKey(const Vec3& a, const Vec3& b) {
  const Point p{a.x, a.y, a.z}, q{b.x, b.y, b.z};
  return std::minmax(p, q);
}

// How B may behave across the edge two elements share: -2 when they share no whole edge (a
// T-vertex, or only a corner), else the continuity order the mesh gives it (C1 untagged).
class EdgeContinuity {
 public:
  explicit EdgeContinuity(const RadiosityMesh& mesh) : mesh_(mesh) {
    // By position: the two sides of a C-1 edge have their own nodes at the same places.
    for (const DiscontinuityEdge& d : mesh.discontinuities)
      tags_[edgeKey(mesh.nodes[d.a].position, mesh.nodes[d.b].position)] = int(d.order);
  }
  int between(uint32_t a, uint32_t b) const {
    const std::vector<Vec3> pa = mesh_.cornerPositions(a), pb = mesh_.cornerPositions(b);
    for (size_t i = 0; i < pa.size(); ++i) {
      const EdgeKey key = edgeKey(pa[i], pa[(i + 1) % pa.size()]);
      for (size_t j = 0; j < pb.size(); ++j)
        if (edgeKey(pb[j], pb[(j + 1) % pb.size()]) == key) {
          const auto tag = tags_.find(key);
          return tag == tags_.end() ? int(Continuity::C1) : tag->second;
        }
    }
    return -2;
  }

 private:
  const RadiosityMesh& mesh_;
  std::map<EdgeKey, int> tags_;
};

}  // namespace

EdgeStencils edgeStencils(const RadiosityMesh& mesh, const std::vector<int32_t>& elementAt, int width, int height) {
  const EdgeContinuity continuity(mesh);
  std::map<std::pair<int32_t, int32_t>, int> known;
  const double diagonal = mesh.bounds().diagonal();
  auto classify = [&](int32_t a, int32_t b) {
    const auto [it, added] = known.emplace(std::minmax(a, b), -2);
    if (!added) return it->second;
    const Element &ea = mesh.elements[a], &eb = mesh.elements[b];
    const bool emits = mesh.materials[ea.material].isEmitter() || mesh.materials[eb.material].isEmitter();
    if (!emits && coplanarElements(mesh, size_t(a), size_t(b), diagonal))
      it->second = continuity.between(uint32_t(a), uint32_t(b));
    return it->second;
  };
  EdgeStencils stencils;
  auto consider = [&](uint32_t p0, uint32_t p1, uint32_t p2, uint32_t p3) {
    const int32_t a = elementAt[p1], b = elementAt[p2];
    if (a < 0 || b < 0 || a == b || elementAt[p0] != a || elementAt[p3] != b) return;
    const int order = classify(a, b);
    if (order == int(Continuity::C1)) stencils.smooth.push_back({p0, p1, p2, p3});
    if (order == int(Continuity::C0)) stencils.c0.push_back({p0, p1, p2, p3});
  };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x + 3 < width; ++x) {
      const uint32_t p = uint32_t(y * width + x);
      consider(p, p + 1, p + 2, p + 3);
    }
  for (int y = 0; y + 3 < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint32_t p = uint32_t(y * width + x), w = uint32_t(width);
      consider(p, p + w, p + 2 * w, p + 3 * w);
    }
  return stencils;
}

double meanGradientJump(const LinearImage& image, double exposureScale,
                        const std::vector<std::array<uint32_t, 4>>& stencils) {
  auto L = [&](uint32_t p, bool& ok) {
    const float* px = &image.rgba[size_t(p) * 4];
    ok = ok && px[3] > 0.5f && std::isfinite(px[0]) && std::isfinite(px[1]) && std::isfinite(px[2]);
    return 255.0 * luminance(displayed(Rgb(px[0], px[1], px[2]), exposureScale));
  };
  double sum = 0.0;
  size_t count = 0;
  for (const auto& s : stencils) {
    bool ok = true;
    const double jump = (L(s[3], ok) - L(s[2], ok)) - (L(s[1], ok) - L(s[0], ok));
    if (!ok) continue;
    sum += std::abs(jump);
    ++count;
  }
  return count ? sum / double(count) : 0.0;
}

}  // namespace radview
