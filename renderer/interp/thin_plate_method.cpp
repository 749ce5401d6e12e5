// Method::ThinPlate on the CPU: Clough-Tocher's patches over the thin-plate smoothing spline's
// values (thin_plate.h), their gradients estimated from those values as for any mesh without
// stored ones (the stored gradients belong to the values before smoothing).
#include "interp/methods.h"
#include "interp/thin_plate.h"
#include "mesh/topology.h"

namespace radview {

namespace {

class ThinPlateInterpolant : public Interpolant {
 public:
  ThinPlateInterpolant(const RadiosityMesh& mesh, const InterpolantOptions& options)
      : smoothed_(smoothThinPlate(mesh, MeshTopology(mesh), options.thinPlate)) {
    InterpolantOptions cloughTocher = options;
    cloughTocher.useStoredGradients = false;
    pieces_ = makeCloughTocher(smoothed_, cloughTocher);
  }
  Sample evaluate(uint32_t element, const Vec3& x) const override { return pieces_->evaluate(element, x); }

 private:
  RadiosityMesh smoothed_;
  std::unique_ptr<Interpolant> pieces_;
};

}  // namespace

std::unique_ptr<Interpolant> makeThinPlate(const RadiosityMesh& mesh, const InterpolantOptions& options) {
  return std::make_unique<ThinPlateInterpolant>(mesh, options);
}

}  // namespace radview
