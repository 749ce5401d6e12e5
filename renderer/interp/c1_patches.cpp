#include "interp/c1_patches.h"

#include <optional>

namespace radview {

namespace {

std::array<Rgb, 3> values(const SurfaceTriangulation& surface, uint32_t t) {
  const auto& n = surface.triangles()[t].node;
  const auto& nodes = surface.mesh().nodes;
  return {nodes[n[0]].B, nodes[n[1]].B, nodes[n[2]].B};
}

// The triangle across edge k when B must be C1 there, else nothing.
std::optional<uint32_t> smoothNeighbour(const SurfaceTriangulation& surface, uint32_t t, int k) {
  const SurfaceTriangle& triangle = surface.triangles()[t];
  if (triangle.neighbour[k] < 0 || triangle.continuity[k] != Continuity::C1) return std::nullopt;
  return uint32_t(triangle.neighbour[k]);
}

Vec3 centroidOf(const std::array<Vec3, 3>& p) { return (p[0] + p[1] + p[2]) / 3.0; }

}  // namespace

std::vector<CloughTocherPatch> buildCloughTocherPatches(const SurfaceTriangulation& surface,
                                                        const CornerGradients& gradients,
                                                        CloughTocherVariant variant) {
  const uint32_t count = uint32_t(surface.triangles().size());
  std::vector<CloughTocherPatch> patches;
  patches.reserve(count);
  for (uint32_t t = 0; t < count; ++t) {
    const auto V = surface.positions(t);
    const Vec3 C = centroidOf(V);
    std::array<CrossBoundary, 3> edges;
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = V[k], &b = V[(k + 1) % 3];
      const std::optional<uint32_t> across = smoothNeighbour(surface, t, k);
      // Both sides of a C1 edge derive the same direction (up to sign), so their cross
      // derivatives, linear along the edge between the shared corner gradients, agree.
      edges[k].d = variant == CloughTocherVariant::Book
                       ? bookCrossDirection(a, b, C)
                       : affineCrossDirection(
                             a, b, C, across ? std::optional<Vec3>(centroidOf(surface.positions(*across))) : std::nullopt);
    }
    patches.push_back(buildCloughTocher(V, values(surface, t), gradients[t], edges));
  }
  return patches;
}

std::vector<PowellSabinPatch> buildPowellSabinPatches(const SurfaceTriangulation& surface,
                                                      const CornerGradients& gradients) {
  const uint32_t count = uint32_t(surface.triangles().size());
  std::vector<Vec3> Z(count);
  for (uint32_t t = 0; t < count; ++t) {
    const auto V = surface.positions(t);
    Z[t] = incenter(V[0], V[1], V[2]);
  }
  std::vector<PowellSabinPatch> patches;
  patches.reserve(count);
  for (uint32_t t = 0; t < count; ++t) {
    const auto V = surface.positions(t);
    std::array<Vec3, 3> R;
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = V[k], &b = V[(k + 1) % 3];
      const std::optional<uint32_t> across = smoothNeighbour(surface, t, k);
      R[k] = across ? edgeSplitPoint(a, b, Z[t], Z[*across]) : 0.5 * (a + b);
    }
    patches.push_back(buildPowellSabin(V, values(surface, t), gradients[t], R));
  }
  return patches;
}

}  // namespace radview
