// Measured convergence order under mesh refinement (the requirement 4): the max error
// of each method on a smooth function, B = (sin 3x cos 2y + 2, e^(x-y), 1 + x^2 y) on [0,1]^2,
// over meshes of n = 4, 8, 16, 32, 64 cells a side. The meshes are a jittered 4 x 4 triangle
// grid refined by midpoint subdivision, so every level has the same triangle shapes and the
// measured order is not blurred by re-jittering; errors are the max over fixed barycentric
// points of every element (vertices excluded), so the sample sets are similar too. The order
// is the least-squares slope of log(error) against log(h) over n = 8 .. 64.
//
// Expected, and asserted within the windows below:
//  - linear: 2 (interpolation error h^2 |D^2 B|).
//  - C1 methods (Powell-Sabin, both Clough-Tocher variants) with exact gradients: 3 (they
//    reproduce quadratics).
//  - the same with gradients estimated by least squares on linear elements: 2. The
//    least-squares plane through a vertex's neighbours has an O(h) gradient error on a
//    general (jittered) mesh, not O(h^2): the fit's first-order error cancels only on
//    stencils symmetric about the vertex. An O(h) slope error at distance h is an O(h^2)
//    value error, so the C1 methods converge no faster than linear here (smaller constant).
//  - quadratic Lagrange, and the C1 methods with fig. 9.10's parabola gradients on quadratic
//    elements: 3 (the parabolas are exact for quadratics, so the gradients are O(h^2)).
#include "interp/interpolant.h"
#include "tests/interp/test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace radview {
namespace {

using namespace test;

const Plane plane;

Rgb smooth(const Vec2& p) {
  return Rgb(std::sin(3 * p.x) * std::cos(2 * p.y) + 2, std::exp(p.x - p.y), 1 + p.x * p.x * p.y);
}
std::array<Vec2, 3> smoothGradient(const Vec2& p) {
  return {Vec2(3 * std::cos(3 * p.x) * std::cos(2 * p.y), -2 * std::sin(3 * p.x) * std::sin(2 * p.y)),
          Vec2(std::exp(p.x - p.y), -std::exp(p.x - p.y)), Vec2(2 * p.x * p.y, p.x * p.x)};
}

const int kCells[] = {4, 8, 16, 32, 64};

// The meshes of the study, coarsest first: linear triangles, with exact gradients stored.
const std::vector<RadiosityMesh>& linearMeshes() {
  static const std::vector<RadiosityMesh> meshes = [] {
    std::vector<RadiosityMesh> out = {gridMesh(4, false, 0.3, smooth, 11, plane)};
    while (out.size() < std::size(kCells)) out.push_back(refined(out.back(), smooth, plane));
    for (RadiosityMesh& mesh : out) setGradients(mesh, smoothGradient, plane);
    return out;
  }();
  return meshes;
}

double maxError(const RadiosityMesh& mesh, const MethodCase& m) {
  static const Vec3 weights[] = {{1.0 / 3, 1.0 / 3, 1.0 / 3},
                                 {0.5, 0.5, 0.0},
                                 {0.0, 0.5, 0.5},
                                 {0.5, 0.0, 0.5},
                                 {0.6, 0.2, 0.2},
                                 {0.2, 0.6, 0.2},
                                 {0.2, 0.2, 0.6},
                                 {0.1, 0.45, 0.45},
                                 {0.45, 0.1, 0.45},
                                 {0.45, 0.45, 0.1}};
  const auto interpolant = makeInterpolant(mesh, m.method, m.options);
  double worst = 0.0;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    const auto& c = mesh.elements[e].corners;
    for (const Vec3& w : weights) {
      const Vec3 x =
          w.x * mesh.nodes[c[0]].position + w.y * mesh.nodes[c[1]].position + w.z * mesh.nodes[c[2]].position;
      const Rgb d = interpolant->evaluate(e, x).B - smooth(plane.coords(x));
      worst = std::max({worst, std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    }
  }
  return worst;
}

struct Study {
  std::vector<double> errors;
  double order = 0.0;  // least-squares slope over n = 8 .. 64
};

Study study(const MethodCase& m, bool storedGradients, bool quadraticElements) {
  Study out;
  for (const RadiosityMesh& linear : linearMeshes()) {
    RadiosityMesh mesh = quadraticElements ? withMidEdgeNodes(linear, smooth, plane) : linear;
    mesh.hasGradients = storedGradients;
    out.errors.push_back(maxError(mesh, m));
  }
  // Slope of log e against log(1/n) over the finest four levels.
  out.order = observedOrder({std::begin(kCells) + 1, std::end(kCells)}, {out.errors.begin() + 1, out.errors.end()});
  return out;
}

void report(const std::string& label, const Study& s) {
  std::printf("[ figures  ] %-62s", label.c_str());
  for (double e : s.errors) std::printf(" %9.3g", e);
  std::printf("   order %.2f\n", s.order);
}

void expectOrder(const std::string& label, const Study& s, double low, double high) {
  report(label, s);
  EXPECT_GE(s.order, low) << label;
  EXPECT_LE(s.order, high) << label;
}

TEST(Convergence, LinearIsSecondOrder) {
  std::printf("[ figures  ] %-62s %9s %9s %9s %9s %9s\n", "max error at n =", "4", "8", "16", "32", "64");
  expectOrder("gouraud", study({"gouraud", Method::Gouraud, {}}, false, false), 1.8, 2.2);
}

TEST(Convergence, C1MethodsAreThirdOrderWithExactGradients) {
  for (const MethodCase& m : c1Methods(true))
    expectOrder(m.name + ", exact gradients", study(m, true, false), 2.7, 3.3);
}

TEST(Convergence, C1MethodsAreSecondOrderWithLeastSquaresGradients) {
  for (const MethodCase& m : c1Methods(false))
    expectOrder(m.name + ", least-squares gradients", study(m, false, false), 1.8, 2.2);
}

TEST(Convergence, QuadraticElementsAreThirdOrder) {
  expectOrder("quadratic (quadratic elements)", study({"quadratic", Method::Quadratic, {}}, false, true), 2.7, 3.3);
  for (const MethodCase& m : c1Methods(false))
    expectOrder(m.name + ", parabola gradients (quadratic elements)", study(m, false, true), 2.7, 3.3);
}

}  // namespace
}  // namespace radview
