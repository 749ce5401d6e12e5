#include "interp/c1_patches.h"

#include "core/parallel_for.h"

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

CloughTocherPatch cloughTocherPatch(const SurfaceTriangulation& surface, const CornerGradients& gradients,
                                    CloughTocherVariant variant, uint32_t t) {
  const auto V = surface.positions(t);
  const Vec3 C = centroidOf(V);
  std::array<CrossBoundary, 3> edges;
  for (int k = 0; k < 3; ++k) {
    const Vec3 &a = V[k], &b = V[(k + 1) % 3];
    const std::optional<uint32_t> across = smoothNeighbour(surface, t, k);
    // Both sides of a C1 edge derive the same direction (up to sign), so their cross
    // derivatives, linear along the edge between the shared corner gradients, agree.
    edges[k].d =
        variant == CloughTocherVariant::Book
            ? bookCrossDirection(a, b, C)
            : affineCrossDirection(a, b, C,
                                   across ? std::optional<Vec3>(centroidOf(surface.positions(*across))) : std::nullopt);
  }
  return buildCloughTocher(V, values(surface, t), gradients[t], edges);
}

std::vector<CloughTocherPatch> buildCloughTocherPatches(const SurfaceTriangulation& surface,
                                                        const CornerGradients& gradients, CloughTocherVariant variant) {
  std::vector<CloughTocherPatch> patches(surface.triangles().size());
  parallelFor(patches.size(),
              [&](size_t t) { patches[t] = cloughTocherPatch(surface, gradients, variant, uint32_t(t)); });
  return patches;
}

namespace {

Vec3 incenterOf(const SurfaceTriangulation& surface, uint32_t t) {
  const auto V = surface.positions(t);
  return incenter(V[0], V[1], V[2]);
}

}  // namespace

PowellSabinPatch powellSabinPatch(const SurfaceTriangulation& surface, const CornerGradients& gradients, uint32_t t) {
  const auto V = surface.positions(t);
  const Vec3 Z = incenter(V[0], V[1], V[2]);
  std::array<Vec3, 3> R;
  for (int k = 0; k < 3; ++k) {
    const Vec3 &a = V[k], &b = V[(k + 1) % 3];
    const std::optional<uint32_t> across = smoothNeighbour(surface, t, k);
    R[k] = across ? edgeSplitPoint(a, b, Z, incenterOf(surface, *across)) : 0.5 * (a + b);
  }
  return buildPowellSabin(V, values(surface, t), gradients[t], R);
}

std::vector<PowellSabinPatch> buildPowellSabinPatches(const SurfaceTriangulation& surface,
                                                      const CornerGradients& gradients) {
  std::vector<PowellSabinPatch> patches(surface.triangles().size());
  parallelFor(patches.size(), [&](size_t t) { patches[t] = powellSabinPatch(surface, gradients, uint32_t(t)); });
  return patches;
}

}  // namespace radview
