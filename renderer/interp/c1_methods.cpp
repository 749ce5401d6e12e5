// The C1 interpolants over the whole mesh: the patches of c1_patches.h, evaluated in the
// triangle of the element that holds the point.
#include "interp/c1_patches.h"
#include "interp/methods.h"

namespace radview {

namespace {

template <typename Patch>
class C1Interpolant : public Interpolant {
 public:
  template <typename Build>
  C1Interpolant(const RadiosityMesh& mesh, const InterpolantOptions& options, Build build)
      : surface_(mesh), patches_(build(surface_, vertexGradients(surface_, options.useStoredGradients))) {}

  Sample evaluate(uint32_t element, const Vec3& x) const override {
    const Patch& patch = patches_[surface_.locate(element, x).triangle];
    return radview::evaluate(patch, patch.frame(x));
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

std::unique_ptr<Interpolant> makePowellSabin(const RadiosityMesh& mesh, const InterpolantOptions& options) {
  return std::make_unique<C1Interpolant<PowellSabinPatch>>(
      mesh, options, [](const SurfaceTriangulation& surface, const CornerGradients& gradients) {
        return buildPowellSabinPatches(surface, gradients);
      });
}

}  // namespace radview
