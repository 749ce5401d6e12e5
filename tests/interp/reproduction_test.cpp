// What every interpolant reproduces on whole meshes (the requirements 1 and 2):
// nodal values at the nodes, and polynomials up to the degree each method is exact for, on
// seeded random meshes in an arbitrary 3D plane, slivers included. A failure prints the seed,
// the method and the element with its nodes.
//
// What each method reproduces, as measured here and pinned by these tests:
//  - linear and bilinear: linear data (bilinear: on parallelograms also x y; on triangles it
//    is linear); quadratic Lagrange: quadratics on its 6-node triangles.
//  - c1-quadratic (Powell-Sabin) and Clough-Tocher (both variants), with exact gradients:
//    every quadratic, exactly; not cubics (the reduced Clough-Tocher element makes the cross
//    derivative linear along each edge, so it is cubic-exact only with the full element's
//    mid-edge derivatives, which the mesh does not carry; Powell-Sabin is piecewise quadratic).
//  - the same with estimated gradients: linear data on linear elements (the least-squares
//    plane fits linear data exactly), every quadratic on quadratic elements (the parabolas of
//    fig. 9.10 are exact for quadratics).
#include "geom/polygon.h"
#include "interp/interpolant.h"
#include "tests/interp/test_meshes.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

using namespace test;

const Plane plane;
constexpr double eps = std::numeric_limits<double>::epsilon();

// A quadratic polynomial per channel, a0 + a1 x + a2 y + a3 x^2 + a4 x y + a5 y^2, with its
// exact gradient.
struct Quadratic {
  std::array<std::array<double, 6>, 3> a{};
  Rgb operator()(const Vec2& p) const {
    Rgb out;
    for (int c = 0; c < 3; ++c)
      out[c] =
          a[c][0] + a[c][1] * p.x + a[c][2] * p.y + a[c][3] * p.x * p.x + a[c][4] * p.x * p.y + a[c][5] * p.y * p.y;
    return out;
  }
  std::array<Vec2, 3> gradient(const Vec2& p) const {
    std::array<Vec2, 3> out;
    for (int c = 0; c < 3; ++c)
      out[c] = {a[c][1] + 2 * a[c][3] * p.x + a[c][4] * p.y, a[c][2] + a[c][4] * p.x + 2 * a[c][5] * p.y};
    return out;
  }
};
Quadratic randomQuadratic(uint32_t seed, bool linearOnly = false) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coefficient(-2.0, 2.0);
  Quadratic q;
  for (auto& channel : q.a)
    for (int i = 0; i < 6; ++i) channel[i] = i >= 3 && linearOnly ? 0.0 : coefficient(random);
  for (auto& channel : q.a) channel[0] += 5.0;  // away from zero, so "relative" means something
  return q;
}

// The meshes of the property tests: jittered triangles with slivers (aspect up to maxAspect),
// jittered quads, and both made quadratic (mid-edge nodes).
struct TestMesh {
  std::string name;
  RadiosityMesh mesh;
};
std::vector<TestMesh> randomMeshes(uint32_t seed, double maxAspect, const Field& f) {
  const int n = 4 + int(seed % 4);
  const RadiosityMesh slivers = sliverMesh(n, maxAspect, 0.3, f, seed, plane);
  // Jitter 0.3 makes some quads non-convex (bilinear and serendipity quads then fall back to
  // linear interpolation).
  const RadiosityMesh quads = gridMesh(n, true, 0.3, f, seed, plane);
  return {{"slivers", slivers},
          {"quads", quads},
          {"quadratic slivers", withMidEdgeNodes(slivers, f, plane)},
          {"quadratic quads", withMidEdgeNodes(quads, f, plane)}};
}

std::vector<MethodCase> methodsWith(bool storedGradients) { return allMethods(storedGradients); }

TEST(MeshReproduction, EveryMethodInterpolatesTheNodalValuesAtNodes) {
  // |B(node) - B_node| <= 64 eps * aspect * (largest |B| of the element): the barycentric
  // coordinates of a corner are exact to ~eps * aspect, not exactly (1, 0, 0) (see
  // BarycentricFrame), and the other corners' values leak in that much. Measured: <= 7.
  double worst = 0.0;
  for (uint32_t seed = 1; seed <= 16; ++seed) {
    const Quadratic q = randomQuadratic(seed);
    for (TestMesh& test : randomMeshes(seed, 1e4, q)) {
      setGradients(
          test.mesh, [&](const Vec2& p) { return q.gradient(p); }, plane);
      for (bool stored : {true, false}) {
        test.mesh.hasGradients = stored;
        for (const MethodCase& m : methodsWith(true)) {
          const auto interpolant = makeInterpolant(test.mesh, m.method, m.options);
          for (uint32_t e = 0; e < test.mesh.elements.size(); ++e) {
            const Element& element = test.mesh.elements[e];
            std::vector<uint32_t> nodes = element.corners;
            // Quadratic Lagrange passes through the mid-edge values too, except on a non-convex
            // quad, which it interpolates linearly over the corners (see quadratic_lagrange.cpp).
            const bool serendipity = element.corners.size() == 3 || isConvex(test.mesh.cornerPositions(e));
            if (m.method == Method::Quadratic && serendipity)
              nodes.insert(nodes.end(), element.midEdge.begin(), element.midEdge.end());
            const double bound = eps * elementAspect(test.mesh, e) * maxAbsB(test.mesh, {e});
            for (uint32_t n : nodes) {
              const Rgb error = interpolant->evaluate(e, test.mesh.nodes[n].position).B - test.mesh.nodes[n].B;
              const double e1 = std::max({std::abs(error.x), std::abs(error.y), std::abs(error.z)});
              worst = std::max(worst, e1 / bound);
              ASSERT_LE(e1, 64.0 * bound) << "seed " << seed << ", " << test.name << " mesh, " << m.name
                                          << (stored ? ", stored" : ", estimated") << " gradients, node " << n << " of "
                                          << describe(test.mesh, e);
            }
          }
        }
      }
    }
  }
  std::printf("[ figures  ] nodal interpolation: worst error %.3g eps * aspect * max|B|\n", worst);
}

TEST(MeshReproduction, LinearDataIsReproducedByEveryMethodFromEstimatedGradients) {
  // Linear and bilinear need no gradients; the C1 methods' least-squares gradients are exact
  // for linear data, so they reproduce it too. Tolerance: 64 eps * aspect of the scale.
  for (uint32_t seed = 1; seed <= 8; ++seed) {
    const Quadratic q = randomQuadratic(100 + seed, true);
    for (TestMesh& test : randomMeshes(seed, 1e3, q)) {
      if (test.name.rfind("quadratic", 0) == 0) continue;  // the quadratic case is the next test
      for (const MethodCase& m : methodsWith(false)) {
        const auto interpolant = makeInterpolant(test.mesh, m.method, m.options);
        std::mt19937 random(seed);
        for (uint32_t e = 0; e < test.mesh.elements.size(); ++e) {
          const double bound = 64 * eps * elementAspect(test.mesh, e) * maxAbsB(test.mesh, {e});
          for (int k = 0; k < 8; ++k) {
            const Vec3 x = randomPointIn(test.mesh, e, random);
            const Rgb error = interpolant->evaluate(e, x).B - q(plane.coords(x));
            ASSERT_LE(glm::length(error), bound) << "seed " << seed << ", " << test.name << " mesh, " << m.name
                                                 << ", at " << str(x) << " in " << describe(test.mesh, e);
          }
        }
      }
    }
  }
}

// Max over random points of every element of |B - q| / max|q|, and of the gradient's error
// in units of eps * aspect * max|B| / height, aspect and height those of the worst element
// around the element's vertices (its round-off: barycentric coordinates good to eps *
// aspect, differentiated over the height; gradients at the vertices estimated from, and
// Powell-Sabin split points placed by, the neighbours).
struct Errors {
  double value = 0.0, gradient = 0.0;
  double valueRoundOff = 0.0;  // |B - q| in units of eps * aspect * max|B|, aspect as for the gradient
  std::string where;           // the worst element, with its nodes
};
Errors reproductionErrors(const RadiosityMesh& mesh, const MethodCase& m, const Quadratic& q, uint32_t seed) {
  const auto interpolant = makeInterpolant(mesh, m.method, m.options);
  double scale = 0.0;
  for (const Node& n : mesh.nodes) scale = std::max(scale, glm::length(n.B));
  std::mt19937 random(seed);
  Errors out;
  const std::vector<Neighbourhood> around = neighbourhoods(mesh);
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    const double gradientScale = eps * around[e].aspect * maxAbsB(mesh, {e}) / around[e].height;
    for (int k = 0; k < 10; ++k) {
      const Vec3 x = randomPointIn(mesh, e, random);
      const Vec2 p = plane.coords(x);
      const Sample s = interpolant->evaluate(e, x);
      const double value = glm::length(s.B - q(p)) / scale;
      out.valueRoundOff =
          std::max(out.valueRoundOff, glm::length(s.B - q(p)) / (eps * around[e].aspect * maxAbsB(mesh, {e})));
      double gradient = 0.0;
      const auto want = q.gradient(p);
      for (int c = 0; c < 3; ++c)
        gradient = std::max(gradient, glm::length(s.gradient[c] - worldGradient(want[c], plane)) / gradientScale);
      if (value > out.value || gradient > out.gradient) out.where = "at " + str(x) + " in " + describe(mesh, e);
      out.value = std::max(out.value, value);
      out.gradient = std::max(out.gradient, gradient);
    }
  }
  return out;
}

TEST(MeshReproduction, C1MethodsReproduceEveryQuadraticGivenItsGradients) {
  // The issue asks 1e-12 relative (float64): met on meshes with slivers up to aspect 1e3
  // (measured <= 2e-14). The gradient is exact to round-off, which on a sliver is not small
  // relative to the gradient: <= 64 eps * aspect * max|B| / height (see reproductionErrors).
  double worstValue = 0.0, worstGradient = 0.0;
  for (uint32_t seed = 1; seed <= 16; ++seed) {
    const Quadratic q = randomQuadratic(200 + seed);
    RadiosityMesh mesh = sliverMesh(4 + int(seed % 5), 1e3, 0.3, q, seed, plane);
    setGradients(
        mesh, [&](const Vec2& p) { return q.gradient(p); }, plane);
    for (const MethodCase& m : c1Methods(true)) {
      const Errors errors = reproductionErrors(mesh, m, q, seed);
      EXPECT_LE(errors.value, 1e-12) << "seed " << seed << ", " << m.name << ", worst " << errors.where;
      EXPECT_LE(errors.gradient, 64.0) << "seed " << seed << ", " << m.name << ", worst " << errors.where;
      worstValue = std::max(worstValue, errors.value);
      worstGradient = std::max(worstGradient, errors.gradient);
    }
  }
  std::printf(
      "[ figures  ] quadratic reproduction, exact gradients: value %.3g relative, gradient %.3g eps aspect B / h\n",
      worstValue, worstGradient);
}

TEST(MeshReproduction, OnQuadraticElementsTheEstimatedGradientsReproduceQuadraticsToo) {
  // Fig. 9.10's parabolas through vertex, mid-edge and far vertex are exact for a quadratic,
  // so the C1 methods reproduce it without stored gradients; so does quadratic Lagrange.
  double worst = 0.0;
  for (uint32_t seed = 1; seed <= 16; ++seed) {
    const Quadratic q = randomQuadratic(300 + seed);
    const RadiosityMesh mesh = withMidEdgeNodes(sliverMesh(4 + int(seed % 3), 1e3, 0.3, q, seed, plane), q, plane);
    std::vector<MethodCase> methods = c1Methods(false);
    methods.push_back({"quadratic", Method::Quadratic, {}});
    for (const MethodCase& m : methods) {
      // Gradients estimated next to a sliver are good to ~eps * its aspect: values and
      // gradients are exact to round-off in those units (measured over 60 seeds: <= 40 and
      // <= 85), which is ~1e-12 relative at aspect 1e3.
      const Errors errors = reproductionErrors(mesh, m, q, seed);
      EXPECT_LE(errors.valueRoundOff, 256.0) << "seed " << seed << ", " << m.name << ", worst " << errors.where;
      EXPECT_LE(errors.gradient, 256.0) << "seed " << seed << ", " << m.name << ", worst " << errors.where;
      worst = std::max(worst, errors.valueRoundOff);
    }
  }
  std::printf(
      "[ figures  ] quadratic reproduction on quadratic elements, estimated gradients: value %.3g eps aspect B\n",
      worst);
}

TEST(MeshReproduction, NoMethodReproducesCubics) {
  // x^3 with its exact gradients: the reduced Clough-Tocher element is not cubic-exact (its
  // cross derivative is linear along each edge, the cubic's is quadratic), nor is anything
  // else here: errors of 1e-3 .. 1e-1 on a 4 x 4 mesh, far above round-off.
  const Field cubic = [](const Vec2& p) { return Rgb(p.x * p.x * p.x, p.y * p.y * p.y, p.x * p.x * p.y); };
  const GradientField gradient = [](const Vec2& p) {
    return std::array<Vec2, 3>{Vec2(3 * p.x * p.x, 0), Vec2(0, 3 * p.y * p.y), Vec2(2 * p.x * p.y, p.x * p.x)};
  };
  RadiosityMesh mesh = gridMesh(4, false, 0.3, cubic, 7, plane);
  setGradients(mesh, gradient, plane);
  const RadiosityMesh quadratic = withMidEdgeNodes(mesh, cubic, plane);
  for (const MethodCase& m : allMethods(true)) {
    const RadiosityMesh& used = m.method == Method::Quadratic ? quadratic : mesh;
    const auto interpolant = makeInterpolant(used, m.method, m.options);
    std::mt19937 random(1);
    double worst = 0.0;
    for (uint32_t e = 0; e < used.elements.size(); ++e)
      for (int k = 0; k < 10; ++k) {
        const Vec3 x = randomPointIn(used, e, random);
        worst = std::max(worst, glm::length(interpolant->evaluate(e, x).B - cubic(plane.coords(x))));
      }
    EXPECT_GT(worst, 1e-4) << m.name << " reproduces a cubic?";
    std::printf("[ figures  ] cubic x^3, y^3, x^2 y on a 4 x 4 mesh, exact gradients: %-24s max error %.3g\n",
                m.name.c_str(), worst);
  }
}

}  // namespace
}  // namespace radview
