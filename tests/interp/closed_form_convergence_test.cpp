// Convergence order of the interpolants (C&W §9.2) against an answer none of radview computed:
// the receiver of tests/closed_form_scenes.h, under a parallel and a tilted emitter, meshed by
// radview's uniform mesher at element sizes h = 1/8, 1/16, 1/32, every node given the exact
// radiosity of Lambert's formula. The error is the RMSE over a fixed set of seeded random
// points of the receiver (every channel), so it measures the interpolant alone: nodal values
// are exact, nothing is solved. The order is the slope of log RMSE against log h.
//
// The mesher cuts the unit square into a grid of square quads. Only the receiver is meshed:
// the emitter reflects nothing and is never sampled, and no node is shared across polygons,
// so its elements could not change the receiver's interpolant.
//
// Expected orders, and what is asserted (least-squares slope over the three sizes; a third
// order method's slope comes out a little above 3 while its error constant is still settling,
// hence the upper bounds of 3.6):
//  - flat: 1 (the element's mean is the value at its centre; the error grows as the gradient
//    times the distance from it). Asserted in [0.8, 1.2].
//  - gouraud and bilinear: 2 (linear interpolation, error h^2 |D^2 B|). Asserted in [1.7, 2.3].
//  - quadratic, on the same grid with mid-edge nodes added (8-node serendipity quads, which
//    reproduce quadratics): 3. Asserted in [2.6, 3.6].
//  - c1-quadratic and clough-tocher (affine and book) reproduce quadratics given exact vertex
//    gradients, so they are third order when the gradients are O(h^2) accurate; an O(h) slope
//    error at distance h is an O(h^2) value error, so a worse gradient caps them:
//      * the closed form's gradients, stored in the mesh: 3. Asserted in [2.6, 3.6].
//      * quadratic elements, fig. 9.10's parabola gradients (exact for quadratics, so O(h^2)
//        at every vertex, on the boundary too): 3. Asserted in [2.6, 3.6].
//      * linear elements, least-squares gradients (vertex_gradients.h). The fitted plane's
//        first-order error cancels on a stencil symmetric about its vertex, which every
//        interior vertex of this grid has (the quads are all cut along the same diagonal, so
//        the neighbours come in opposite pairs): O(h^2) there, and the interpolant is third
//        order away from the boundary. At the boundary the stencil is one-sided and the
//        gradient only O(h); the elements that touch it, O(h) of the area, carry O(h^2)
//        errors, an O(h^2.5) share of the RMSE against the interior's O(h^3). Over the whole
//        receiver the order therefore falls from 3 towards 2.5 as h shrinks (the max error,
//        set at the boundary, would show 2). Asserted: in [2.6, 3.6] over the points more
//        than 1/8 from the receiver's edge (in elements with no boundary vertex at every
//        size), in [2.3, 3.6] over the whole receiver.
// scanline-gouraud is left out: its value depends on where the element lies on the screen
// (fig. 9.8), so a surface point alone has none, and the view's pixels, not h, would set its
// error.
#include "interp/interpolant.h"
#include "interp/surface_locator.h"
#include "mesh/uniform_mesher.h"
#include "tests/closed_form_scenes.h"
#include "tests/interp/test_meshes.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace radview {
namespace {

using namespace test;

// The receiver's plane: the unit square y = 0, (x, z) its coordinates.
const Plane kReceiver{Vec3(0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 0.0, 1.0)};

const int kCells[] = {8, 16, 32};  // h = 1/8, 1/16, 1/32

// The exact surface gradient of B: the fourth-order central difference of Lambert's formula,
// whose O(d^4) error is far below any interpolation error of these meshes. The formula holds
// on the whole plane (the emitter stays above every point's horizon), so boundary nodes need
// no one-sided difference.
std::array<Vec2, 3> exactGradient(const ClosedFormScene& s, const Vec2& p) {
  const double d = 1e-3;
  auto derivative = [&](const Vec2& step) {
    auto B = [&](double k) { return s.B(kReceiver.at(p.x + k * step.x, p.y + k * step.y)); };
    return (B(-2) - 8.0 * B(-1) + 8.0 * B(1) - B(2)) / (12.0 * d);
  };
  const Rgb dx = derivative(Vec2(d, 0.0)), dy = derivative(Vec2(0.0, d));
  return {Vec2(dx.x, dy.x), Vec2(dx.y, dy.y), Vec2(dx.z, dy.z)};
}

// The sample points: uniform on the receiver, the same for every mesh.
const std::vector<Vec3>& samplePoints() {
  static const std::vector<Vec3> points = [] {
    std::mt19937 random(97);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Vec3> out(4000);
    for (Vec3& p : out) {
      const double x = unit(random);
      p = kReceiver.at(x, unit(random));
    }
    return out;
  }();
  return points;
}

// Whether a sample point is more than 1/8 from the receiver's edge: then at h <= 1/8 no
// corner of its element is on the edge.
bool awayFromEdge(const Vec3& p) {
  const Vec2 q = kReceiver.coords(p);
  return std::min({q.x, q.y, 1.0 - q.x, 1.0 - q.y}) > 1.0 / 8.0;
}

struct Level {
  RadiosityMesh linear, quadratic;  // the mesher's quads; the same with mid-edge nodes
  std::vector<SurfacePoint> at;     // each sample point's element (the same in both meshes)
};

std::vector<Level> levels(const ClosedFormScene& s) {
  Scene receiverOnly = s.scene;
  receiverOnly.polygons.resize(1);
  const Field B = [&](const Vec2& p) { return s.B(kReceiver.at(p.x, p.y)); };
  const GradientField gradient = [&](const Vec2& p) { return exactGradient(s, p); };
  std::vector<Level> out;
  for (int n : kCells) {
    Level level;
    level.linear = meshUniformly(receiverOnly, 1.0 / n);
    setValues(level.linear, B, kReceiver);
    setGradients(level.linear, gradient, kReceiver);
    level.quadratic = withMidEdgeNodes(level.linear, B, kReceiver);
    setGradients(level.quadratic, gradient, kReceiver);
    const SurfaceLocator locator(level.linear);
    for (const Vec3& p : samplePoints()) level.at.push_back(locator.nearest(p));
    out.push_back(std::move(level));
  }
  return out;
}

// Over the sample points, or only those away from the receiver's edge.
double rmse(const ClosedFormScene& s, const RadiosityMesh& mesh, const std::vector<SurfacePoint>& at,
            const MethodCase& m, bool awayOnly) {
  const auto interpolant = makeInterpolant(mesh, m.method, m.options);
  double sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < samplePoints().size(); ++i) {
    const Vec3& p = samplePoints()[i];
    if (awayOnly && !awayFromEdge(p)) continue;
    const Rgb d = interpolant->evaluate(at[i].element, at[i].x).B - s.B(p);
    sum += glm::dot(d, d);
    ++count;
  }
  return std::sqrt(sum / (3.0 * double(count)));
}

struct Case {
  MethodCase method;
  bool quadraticElements = false;
  bool awayFromEdgeOnly = false;
};

struct Study {
  std::vector<double> errors;  // at h, h/2, h/4
  double order = 0.0;          // least-squares slope of log error against log h
};

Study study(const ClosedFormScene& s, const std::vector<Level>& meshes, const Case& c) {
  Study out;
  for (const Level& level : meshes)
    out.errors.push_back(
        rmse(s, c.quadraticElements ? level.quadratic : level.linear, level.at, c.method, c.awayFromEdgeOnly));
  out.order = observedOrder({std::begin(kCells), std::end(kCells)}, out.errors);
  return out;
}

void printHeader(const std::string& scene) {
  std::printf("[ figures  ] %s: RMSE at h = 1/8, 1/16, 1/32; log2 of each ratio; least-squares slope\n", scene.c_str());
}

void print(const std::string& label, const Study& s) {
  std::printf("[ figures  ] %-62s", label.c_str());
  for (double e : s.errors) std::printf(" %9.3e", e);
  for (size_t i = 1; i < s.errors.size(); ++i) std::printf(" %5.2f", std::log2(s.errors[i - 1] / s.errors[i]));
  std::printf("   order %.2f\n", s.order);
}

MethodCase withGradients(MethodCase m, bool stored, const std::string& which) {
  m.options.useStoredGradients = stored;
  m.name += ", " + which;
  return m;
}

void expectOrders(const std::string& label, double tiltDegrees) {
  const ClosedFormScene s = emitterOverSquare(tiltDegrees);
  const std::vector<Level> meshes = levels(s);
  printHeader(label);
  auto run = [&](const Case& c, double low, double high) {
    const Study result = study(s, meshes, c);
    print(c.method.name, result);
    EXPECT_GE(result.order, low) << label << ", " << c.method.name;
    EXPECT_LE(result.order, high) << label << ", " << c.method.name;
  };
  run({{"flat", Method::Flat, {}}}, 0.8, 1.2);
  run({{"gouraud", Method::Gouraud, {}}}, 1.7, 2.3);
  run({{"bilinear", Method::Bilinear, {}}}, 1.7, 2.3);
  run({{"quadratic (quadratic elements)", Method::Quadratic, {}}, true}, 2.6, 3.6);
  for (const MethodCase& m : c1Methods()) {
    run({withGradients(m, true, "exact gradients")}, 2.6, 3.6);
    run({withGradients(m, false, "parabola gradients, quadratic elements"), true}, 2.6, 3.6);
    run({withGradients(m, false, "least-squares gradients")}, 2.3, 3.6);
    run({withGradients(m, false, "least-squares gradients, away from edge"), false, true}, 2.6, 3.6);
  }
}

// The answer the orders are measured against is right: at the receiver's centre under the
// parallel emitter, Lambert's formula agrees with the form factor from a differential area to a
// parallel rectangle with a corner above it (Howell's catalogue), summed over the emitter's
// four quarters.
TEST(ClosedFormConvergence, LambertAgreesWithTheRectangleFormula) {
  const ClosedFormScene s = emitterOverSquare();
  // X and Y: the quarter's sides (0.1) over its height (0.5).
  const double X = 0.1 / 0.5, Y = 0.1 / 0.5;
  const double quarter = (X / std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) +
                          Y / std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y))) /
                         (2.0 * glm::pi<double>());
  EXPECT_NEAR(s.formFactor(kReceiver.at(0.5, 0.5)), 4.0 * quarter, 1e-14);
}

TEST(ClosedFormConvergence, ParallelEmitter) { expectOrders("parallel emitter", 0.0); }

TEST(ClosedFormConvergence, EmitterTilted30Degrees) { expectOrders("emitter tilted 30 degrees", 30.0); }

}  // namespace
}  // namespace radview
