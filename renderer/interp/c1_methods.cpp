// The C1 interpolants over the whole mesh: the patches of c1_patches.h, evaluated in the
// triangle of the element that holds the point.
#include "interp/c1_patches.h"
#include "interp/methods.h"

#include <algorithm>
#include <limits>

namespace radview {

namespace {

template <typename Patch>
class C1Interpolant : public Interpolant {
 public:
  template <typename Build>
  C1Interpolant(const RadiosityMesh& mesh, const InterpolantOptions& options, Build build)
      : surface_(mesh), patches_(build(surface_, vertexGradients(surface_, options.useStoredGradients))) {}

  // SurfaceTriangulation::locate's choice of triangle (the one the point is deepest inside),
  // from the frames the patches already hold.
  Sample evaluate(uint32_t element, const Vec3& x) const override {
    const Patch* best = nullptr;
    Vec3 lambda(0.0);
    double bestInside = -std::numeric_limits<double>::infinity();
    for (uint32_t t : surface_.trianglesOf(element)) {
      const Vec3 w = patches_[t].frame(x);
      const double inside = std::min(w.x, std::min(w.y, w.z));
      if (inside > bestInside || !best) {
        bestInside = inside;
        best = &patches_[t];
        lambda = w;
      }
    }
    if (!best) {  // an element left without triangles: locate's answer
      const Patch& patch = patches_[surface_.locate(element, x).triangle];
      return radview::evaluate(patch, patch.frame(x));
    }
    return radview::evaluate(*best, lambda);
  }

 private:
  SurfaceTriangulation surface_;
  std::vector<Patch> patches_;
};

}  // namespace

std::unique_ptr<Interpolant> makeCloughTocher(const RadiosityMesh& mesh, const InterpolantOptions& options) {
  return std::make_unique<C1Interpolant<CloughTocherPatch>>(
      mesh, options, [&](const SurfaceTriangulation& surface, const CornerGradients& gradients) {
        return buildCloughTocherPatches(surface, gradients, options.cloughTocher);
      });
}

std::unique_ptr<Interpolant> makeC1Quadratic(const RadiosityMesh& mesh, const InterpolantOptions& options) {
  return std::make_unique<C1Interpolant<PowellSabinPatch>>(
      mesh, options, [](const SurfaceTriangulation& surface, const CornerGradients& gradients) {
        return buildPowellSabinPatches(surface, gradients);
      });
}

}  // namespace radview
