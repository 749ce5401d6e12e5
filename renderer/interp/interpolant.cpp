#include "interp/interpolant.h"

#include "core/error.h"
#include "core/strings.h"
#include "interp/methods.h"

namespace radview {

std::ostream& operator<<(std::ostream& os, const Sample& s) {
  return os << "B " << s.B << " grad " << s.gradient[0] << ' ' << s.gradient[1] << ' ' << s.gradient[2];
}

const std::vector<std::string>& methodNames() {
  static const std::vector<std::string> names = {"flat",      "linear",       "bilinear",
                                                 "quadratic", "c1-quadratic", "clough-tocher"};
  return names;
}

Method methodFromName(const std::string& name) {
  const auto& names = methodNames();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<Method>(i);
  throw Error("unknown interpolation method '" + name + "' (expected one of " + joined(names) + ")");
}

CloughTocherVariant cloughTocherVariantFromName(const std::string& name) {
  if (name == "affine") return CloughTocherVariant::AffineInvariant;
  if (name == "book") return CloughTocherVariant::Book;
  throw Error("unknown Clough-Tocher variant '" + name + "' (expected affine or book)");
}

std::unique_ptr<Interpolant> makeInterpolant(const RadiosityMesh& mesh, Method method,
                                             const InterpolantOptions& options) {
  switch (method) {
    case Method::Flat: return makeFlat(mesh);
    case Method::Linear: return makeLinear(mesh, options.diagonal);
    case Method::Bilinear: return makeBilinear(mesh);
    case Method::Quadratic: return makeQuadraticLagrange(mesh);
    case Method::C1Quadratic: return makePowellSabin(mesh, options);
    case Method::CloughTocher: return makeCloughTocher(mesh, options);
  }
  throw Error("unknown interpolation method");
}

}  // namespace radview
