#pragma once
// Reconstruction of the radiosity function B(x) from nodal values (C&W §9.2): one interface
// for every method, built once from a mesh, evaluated at points of an element. This is the
// CPU reference the GPU paths are checked against, so it works in double precision.
#include "interp/method_registry.h"
#include "interp/thin_plate.h"
#include "mesh/radiosity_mesh.h"

#include <glm/mat4x4.hpp>

#include <array>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace radview {

// B and its surface gradient at a point. gradient[c] is the world-space gradient of channel
// c, a vector in the element's plane.
struct Sample {
  Rgb B{0.0};
  std::array<Vec3, 3> gradient{};
};

std::ostream& operator<<(std::ostream& os, const Sample& s);

// Which diagonal cuts a quad for Method::Gouraud: corners 0-2 (what radview's GPU Gouraud path
// draws) or 1-3. Fig. 9.7: the two give different pictures from the same data.
enum class QuadDiagonal { D02, D13 };

// Cross-boundary direction of the Clough-Tocher edge wedge (C&W step 3).
enum class CloughTocherVariant {
  AffineInvariant,  // centroid to neighbour centroid (scipy's CloughTocher2DInterpolator)
  Book,             // the edge normal, as the text reads
};

// "affine", "book". Throws Error.
CloughTocherVariant cloughTocherVariantFromName(const std::string& name);

// Where the mesh is seen from, for a method whose value depends on it (Method::ScanlineGouraud):
// the clip-from-world matrix and the viewport in pixels of the image it is drawn in, as
// Camera::clipFromWorld(width / height) and {width, height}.
struct ScreenView {
  glm::dmat4 clipFromWorld{1.0};
  Vec2 viewport{1.0};
};

struct InterpolantOptions {
  QuadDiagonal diagonal = QuadDiagonal::D02;
  std::optional<ScreenView> view;  // required by view-dependent methods, ignored by the others
  CloughTocherVariant cloughTocher = CloughTocherVariant::AffineInvariant;
  // Use the gradients stored in the mesh when it has them (else they are estimated).
  bool useStoredGradients = true;
  ThinPlateSettings thinPlate;  // Method::ThinPlate's smoothing
};

class Interpolant {
 public:
  virtual ~Interpolant() = default;
  // B at `x`, a world-space point of element `element` (points off its plane are projected
  // onto it; points outside it are extrapolated from the nearest piece).
  virtual Sample evaluate(uint32_t element, const Vec3& x) const = 0;
};

// The mesh must outlive the interpolant. Throws Error for a method the mesh cannot support.
std::unique_ptr<Interpolant> makeInterpolant(const RadiosityMesh& mesh, Method method,
                                             const InterpolantOptions& options = {});

// Whether Method::Quadratic evaluates the element as an 8-node serendipity quad: a quadratic
// element with 4 corners, convex (a non-convex quad folds the bilinear map the shape functions
// live on, so it is interpolated linearly instead, like other quadratic polygons).
bool isSerendipityQuad(const RadiosityMesh& mesh, size_t element);
// Whether Method::Quadratic evaluates the element as a 6-node triangle (quadratic, 3 corners).
bool isQuadraticTriangle(const Element& element);

}  // namespace radview
