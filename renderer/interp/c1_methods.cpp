// The C1 interpolants over the whole mesh: the per-triangle elements (clough_tocher.h,
// powell_sabin.h) joined through shared corner gradients and shared edge conditions, on the
// triangulation of surface_triangulation.h. Across edges tagged C0 or C-1, and across creases
// and boundaries, each side is built from its own data alone (Salesin et al. 1992).
#include "interp/clough_tocher.h"
#include "interp/methods.h"
#include "interp/powell_sabin.h"
#include "interp/surface_triangulation.h"
#include "interp/vertex_gradients.h"

#include <optional>

namespace radview {

namespace {

// What every C1 interpolant starts from: the triangulation, and per triangle its corner
// positions, values and gradients.
class C1Base : public Interpolant {
 protected:
  C1Base(const RadiosityMesh& mesh, const InterpolantOptions& options)
      : surface_(mesh), gradients_(vertexGradients(surface_, options.useStoredGradients)) {}

  std::array<Rgb, 3> values(uint32_t t) const {
    const auto& n = surface_.triangles()[t].node;
    const auto& nodes = surface_.mesh().nodes;
    return {nodes[n[0]].B, nodes[n[1]].B, nodes[n[2]].B};
  }
  std::array<RgbGradient, 3> cornerGradients(uint32_t t) const { return gradients_[t]; }
  // The triangle across edge k when B must be C1 there, else nothing.
  std::optional<uint32_t> smoothNeighbour(uint32_t t, int k) const {
    const SurfaceTriangle& triangle = surface_.triangles()[t];
    if (triangle.neighbour[k] < 0 || triangle.continuity[k] != Continuity::C1) return std::nullopt;
    return uint32_t(triangle.neighbour[k]);
  }

  SurfaceTriangulation surface_;
  CornerGradients gradients_;
};

Vec3 centroidOf(const std::array<Vec3, 3>& p) { return (p[0] + p[1] + p[2]) / 3.0; }

class CloughTocher : public C1Base {
 public:
  CloughTocher(const RadiosityMesh& mesh, const InterpolantOptions& options) : C1Base(mesh, options) {
    const size_t count = surface_.triangles().size();
    patches_.reserve(count);
    for (uint32_t t = 0; t < count; ++t) {
      const auto V = surface_.positions(t);
      const Vec3 C = centroidOf(V);
      std::array<CrossBoundary, 3> edges;
      for (int k = 0; k < 3; ++k) {
        const Vec3 &a = V[k], &b = V[(k + 1) % 3];
        const std::optional<uint32_t> across = smoothNeighbour(t, k);
        // Both sides of a C1 edge derive the same direction (up to sign), so their cross
        // derivatives, linear along the edge between the shared corner gradients, agree.
        edges[k].d = options.cloughTocher == CloughTocherVariant::Book
                         ? bookCrossDirection(a, b, C)
                         : affineCrossDirection(a, b, C,
                                                across ? std::optional<Vec3>(centroidOf(surface_.positions(*across)))
                                                       : std::nullopt);
      }
      patches_.push_back(buildCloughTocher(V, values(t), cornerGradients(t), edges));
    }
  }

  Sample evaluate(uint32_t element, const Vec3& x) const override {
    const CloughTocherPatch& patch = patches_[surface_.locate(element, x).triangle];
    return radview::evaluate(patch, patch.frame(x));
  }

 private:
  std::vector<CloughTocherPatch> patches_;
};

// Reichert's C1 quadratic (C&W §9.2.2): Powell-Sabin 6-splits at the incenters, each edge cut
// where the segment between the incenters on its two sides crosses it (its midpoint where
// the edge is not C1), which is what makes the pieces of neighbours join C1.
class PowellSabin : public C1Base {
 public:
  PowellSabin(const RadiosityMesh& mesh, const InterpolantOptions& options) : C1Base(mesh, options) {
    const size_t count = surface_.triangles().size();
    std::vector<Vec3> Z(count);
    for (uint32_t t = 0; t < count; ++t) {
      const auto V = surface_.positions(t);
      Z[t] = incenter(V[0], V[1], V[2]);
    }
    patches_.reserve(count);
    for (uint32_t t = 0; t < count; ++t) {
      const auto V = surface_.positions(t);
      std::array<Vec3, 3> R;
      for (int k = 0; k < 3; ++k) {
        const Vec3 &a = V[k], &b = V[(k + 1) % 3];
        const std::optional<uint32_t> across = smoothNeighbour(t, k);
        R[k] = across ? edgeSplitPoint(a, b, Z[t], Z[*across]) : 0.5 * (a + b);
      }
      patches_.push_back(buildPowellSabin(V, values(t), cornerGradients(t), R));
    }
  }

  Sample evaluate(uint32_t element, const Vec3& x) const override {
    const PowellSabinPatch& patch = patches_[surface_.locate(element, x).triangle];
    return radview::evaluate(patch, patch.frame(x));
  }

 private:
  std::vector<PowellSabinPatch> patches_;
};

}  // namespace

std::unique_ptr<Interpolant> makeCloughTocher(const RadiosityMesh& mesh, const InterpolantOptions& options) {
  return std::make_unique<CloughTocher>(mesh, options);
}

std::unique_ptr<Interpolant> makePowellSabin(const RadiosityMesh& mesh, const InterpolantOptions& options) {
  return std::make_unique<PowellSabin>(mesh, options);
}

}  // namespace radview
