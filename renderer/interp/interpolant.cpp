#include "interp/interpolant.h"

#include "core/error.h"
#include "core/strings.h"
#include "interp/methods.h"

namespace radview {

std::ostream& operator<<(std::ostream& os, const Sample& s) {
  return os << "B " << s.B << " grad " << s.gradient[0] << ' ' << s.gradient[1] << ' ' << s.gradient[2];
}

CloughTocherVariant cloughTocherVariantFromName(const std::string& name) {
  if (name == "affine") return CloughTocherVariant::AffineInvariant;
  if (name == "book") return CloughTocherVariant::Book;
  throw Error("unknown Clough-Tocher variant '" + name + "' (expected affine or book)");
}

std::unique_ptr<Interpolant> makeInterpolant(const RadiosityMesh& mesh, Method method,
                                             const InterpolantOptions& options) {
  switch (method) {
    case Method::Flat:
      return makeFlat(mesh);
    case Method::Gouraud:
      return makeGouraud(mesh, options.diagonal);
    case Method::ScanlineGouraud:
      if (!options.view)
        throw Error(
            "scanline-gouraud depends on where the mesh is on the screen: it needs a view (camera and "
            "image size)");
      return makeScanlineGouraud(mesh, *options.view);
    case Method::Bilinear:
      return makeBilinear(mesh);
    case Method::Quadratic:
      return makeQuadraticLagrange(mesh);
    case Method::C1Quadratic:
      return makeC1Quadratic(mesh, options);
    case Method::CloughTocher:
      return makeCloughTocher(mesh, options);
    case Method::ThinPlate:
      return makeThinPlate(mesh, options);
  }
  throw Error("unknown interpolation method");
}

}  // namespace radview
