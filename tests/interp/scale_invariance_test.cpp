// B reconstructed from nodal values does not depend on the units of length or on where the
// origin is: with every position mapped to origin + s x, each method must give the same B at
// corresponding points, and gradients scaled by 1/s, up to the rounding of the positions
// themselves. Found on the GPU (tests/gl/extremes_render_test.cpp: Clough-Tocher's picture of
// the extreme box at scale 1e-6 off by up to 240 times); both causes were in the CPU's
// SurfaceTriangulation: a Delaunay tie (a square) decided by the positions' rounding, and a
// coplanarity test blind to it far from the origin (delaunayTriangles and the neighbour loop
// in renderer/interp/surface_triangulation.cpp).
#include "interp/interpolant.h"
#include "tests/extreme_scenes.h"
#include "tests/interp/test_meshes.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

namespace radview {
namespace {

using namespace test;

constexpr double eps = std::numeric_limits<double>::epsilon();

// The placements, applied to a mesh about a unit across around the origin (the extreme box's
// "unit" placement): powers of ten both ways, and far from the origin, where a double resolves
// 1.5e-11.
std::vector<Placement> placements() {
  const Vec3 far(1e5, -1e5, 1e5);
  return {{"scale 1e-6", 1e-6, Vec3(0.0)},
          {"scale 1e-3", 1e-3, Vec3(0.0)},
          {"scale 1e3", 1e3, Vec3(0.0)},
          {"scale 1e6", 1e6, Vec3(0.0)},
          {"at 1e5", 1.0, far},
          {"scale 1e-3 at 1e5", 1e-3, far}};
}

// x -> origin + s x, as Placement::place does for the box's unit coordinates minus 1/2, so the
// box placed here and extremeBox(placement) are the same to the last bit.
Vec3 placed(const Placement& placement, const Vec3& x) { return placement.origin + placement.scale * x; }
RadiosityMesh placed(RadiosityMesh mesh, const Placement& placement) {
  for (Node& node : mesh.nodes) node.position = placed(placement, node.position);
  return mesh;
}

// The smallest height of a triangle of consecutive corners: an element's thinnest feature (a
// sliver's width), the length against which positions' rounding counts.
double thinnest(const std::vector<Vec3>& p) {
  double out = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < p.size(); ++k) {
    const Vec3 &a = p[(k + p.size() - 1) % p.size()], &b = p[k], &c = p[(k + 1) % p.size()];
    out = std::min(out, glm::length(glm::cross(b - a, c - a)) / std::max(glm::length(c - a), glm::length(b - a)));
  }
  return out;
}
double thinnest(const RadiosityMesh& mesh) {
  double out = std::numeric_limits<double>::infinity();
  for (size_t e = 0; e < mesh.elements.size(); ++e) out = std::min(out, thinnest(mesh.cornerPositions(e)));
  return out;
}

double largestCoordinate(const RadiosityMesh& mesh) {
  double out = 0.0;
  for (const Node& node : mesh.nodes)
    for (int i = 0; i < 3; ++i) out = std::max(out, std::abs(node.position[i]));
  return out;
}

struct NamedMesh {
  std::string name;
  RadiosityMesh mesh;  // about a unit across, around the origin
};

std::vector<NamedMesh> meshes() {
  // Quadratic elements (their gradients from the parabolas of fig. 9.10), jittered quads and
  // triangles in a tilted plane (no coordinate exact), values from 1 to about 3.
  const Field f = [](const Vec2& p) { return Rgb(1.0 + p.x * p.x + std::sin(3.0 * p.y), 2.0 - p.x * p.y, 1.5); };
  const Plane plane{Vec3(-0.3, -0.2, 0.1)};
  return {{"the extreme box", extremeBox({"unit", 1.0, Vec3(0.0)})},
          {"quadratic quads", withMidEdgeNodes(gridMesh(6, true, 0.2, f, 5, plane), f, plane)},
          {"quadratic triangles", withMidEdgeNodes(gridMesh(6, false, 0.2, f, 6, plane), f, plane)}};
}

// Six points inside each element: random convex combinations of its corners (the meshes'
// elements are convex), off every line through two nodes but by chance: a C0 method's
// gradient jumps across the lines that cut its elements, and on one either side is right.
std::vector<Vec3> pointsOf(const RadiosityMesh& mesh, size_t element, std::mt19937& random) {
  const std::vector<Vec3> corners = mesh.cornerPositions(element);
  std::uniform_real_distribution<double> weight(0.05, 1.0);
  std::vector<Vec3> out;
  for (int i = 0; i < 6; ++i) {
    Vec3 x(0.0);
    double total = 0.0;
    for (const Vec3& corner : corners) {
      const double w = weight(random);
      x += w * corner;
      total += w;
    }
    out.push_back(x / total);
  }
  return out;
}

// The positions of a placed mesh are good to eps |x|; against its thinnest feature that is
//   rho = eps * (largest coordinate) / (s * thinnest),
// a relative change of the geometry that B may follow: 1.1e-10 for the box at any scale
// (slivers 1e-6 wide), 2.2e-5 at 1e5, 2.2e-2 for the box 1e-3 across there. B must agree to
// rho times the element's largest nodal value (measured: at most 0.36 of that), its gradient to
// 4 rho times that value over the element's thinnest height (measured: at most 1.9 rho).
TEST(ScaleInvariance, EveryMethodGivesTheSameBAtEveryScaleAndPlace) {
  std::vector<MethodCase> methods = allMethods(false);
  methods.insert(methods.begin(), MethodCase{"flat", Method::Flat, {}});
  for (const NamedMesh& unit : meshes()) {
    const double feature = thinnest(unit.mesh);
    for (const Placement& placement : placements()) {
      const RadiosityMesh mesh = placed(unit.mesh, placement);
      const double rho = eps * largestCoordinate(mesh) / (placement.scale * feature);
      for (const MethodCase& m : methods) {
        SCOPED_TRACE(unit.name + ", " + placement.name + ", " + m.name);
        const auto reference = makeInterpolant(unit.mesh, m.method, m.options);
        const auto interpolant = makeInterpolant(mesh, m.method, m.options);
        double worstB = 0.0, worstGradient = 0.0;
        std::mt19937 random(7);
        for (uint32_t e = 0; e < unit.mesh.elements.size(); ++e) {
          double largest = 0.0;
          for (uint32_t n : unit.mesh.elements[e].corners)
            for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(unit.mesh.nodes[n].B[c]));
          const double height = thinnest(unit.mesh.cornerPositions(e));
          for (const Vec3& x : pointsOf(unit.mesh, e, random)) {
            const Sample expected = reference->evaluate(e, x);
            const Sample got = interpolant->evaluate(e, placed(placement, x));
            for (int c = 0; c < 3; ++c) {
              const double dB = std::abs(got.B[c] - expected.B[c]) / largest;
              const Vec3 gradientError = placement.scale * got.gradient[c] - expected.gradient[c];
              const double dG = glm::length(gradientError) * height / largest;
              worstB = std::max(worstB, dB);
              worstGradient = std::max(worstGradient, dG);
              ASSERT_LE(dB, rho) << "element " << e << " at " << str(x) << ": " << str(got.B) << " against "
                                 << str(expected.B);
              ASSERT_LE(dG, 4.0 * rho) << "element " << e << " at " << str(x) << ": gradient " << str(got.gradient[c])
                                       << " against " << str(expected.gradient[c]) << " / s";
            }
          }
        }
        std::printf("[ figures  ] %-19s %-17s %-24s B off by %8.2g, gradient by %8.2g (rho %8.2g)\n", unit.name.c_str(),
                    placement.name.c_str(), m.name.c_str(), worstB, worstGradient, rho);
      }
    }
  }
}

}  // namespace
}  // namespace radview
