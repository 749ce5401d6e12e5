// Flat, linear, bilinear and quadratic Lagrange against what each must reproduce, on meshes in
// an arbitrary plane. Relative tolerances are a few hundred ulps of float64.
#include "core/error.h"
#include "interp/interpolant.h"
#include "interp/surface_point.h"
#include "tests/interp/test_meshes.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

using test::gridMesh;
using test::Plane;

const Plane plane;

Rgb linearField(const Vec2& p) { return Rgb(1.0 + 2.0 * p.x - 3.0 * p.y, 0.5 - p.x, 4.0 * p.y); }
Rgb quadraticField(const Vec2& p) {
  return Rgb(1.0 + p.x * p.x - 2.0 * p.x * p.y + 0.5 * p.y * p.y, 2.0 + p.x - p.y * p.y, 3.0 * p.x * p.y);
}
// The world-space gradient of channel c of the linear field.
Vec3 linearGradient(int c) {
  const Vec2 g2 = c == 0 ? Vec2(2.0, -3.0) : c == 1 ? Vec2(-1.0, 0.0) : Vec2(0.0, 4.0);
  return g2.x * plane.u + g2.y * plane.v;
}

// Points spread over each element (barycentric in its first three corners) and at its nodes.
template <typename Check>
void forPointsOf(const RadiosityMesh& mesh, Check check) {
  const Vec3 weights[] = {{0.2, 0.3, 0.5}, {0.6, 0.2, 0.2}, {0.1, 0.1, 0.8}, {1.0 / 3, 1.0 / 3, 1.0 / 3}};
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (const Vec3& w : weights) check(e, pointFromBarycentric(mesh, e, w));
}

TEST(ElementMethods, EveryMethodInterpolatesTheNodalValuesAtNodes) {
  const RadiosityMesh triangles = gridMesh(5, false, 0.3, quadraticField, 1);
  const RadiosityMesh quads = gridMesh(5, true, 0.2, quadraticField, 2);
  const RadiosityMesh quadraticTriangles = test::withMidEdgeNodes(triangles, quadraticField);
  for (const RadiosityMesh* mesh : {&triangles, &quads, &quadraticTriangles})
    for (Method method : {Method::Gouraud, Method::Bilinear, Method::Quadratic}) {
      const auto interpolant = makeInterpolant(*mesh, method);
      for (uint32_t e = 0; e < mesh->elements.size(); ++e) {
        const Element& element = mesh->elements[e];
        std::vector<uint32_t> nodes = element.corners;
        if (method == Method::Quadratic) nodes.insert(nodes.end(), element.midEdge.begin(), element.midEdge.end());
        for (uint32_t n : nodes) {
          const Rgb B = interpolant->evaluate(e, mesh->nodes[n].position).B;
          EXPECT_NEAR(glm::length(B - mesh->nodes[n].B), 0.0, 1e-13 * glm::length(mesh->nodes[n].B))
              << methodName(method) << " element " << e << " node " << n;
        }
      }
    }
}

TEST(ElementMethods, DimNodesKeepTheirOwnValueNextToBrightOnes) {
  // Values from 1e-8 to 1e8 in one element: at each node every method returns that node's
  // value to its own relative precision, not to the precision of the brightest neighbour.
  RadiosityMesh mesh = gridMesh(3, false, 0.3, quadraticField, 11);
  for (size_t i = 0; i < mesh.nodes.size(); ++i) mesh.nodes[i].B = Rgb(i % 2 ? 1e8 : 1e-8, 1.0, i % 3 ? 1e-8 : 1e8);
  for (Method method :
       {Method::Gouraud, Method::Bilinear, Method::Quadratic, Method::C1Quadratic, Method::CloughTocher}) {
    const auto interpolant = makeInterpolant(mesh, method);
    for (uint32_t e = 0; e < mesh.elements.size(); ++e)
      for (uint32_t n : mesh.elements[e].corners) {
        const Rgb got = interpolant->evaluate(e, mesh.nodes[n].position).B, want = mesh.nodes[n].B;
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(got[c], want[c], 1e-12 * want[c]) << methodName(method) << " element " << e << " node " << n;
      }
  }
}

TEST(ElementMethods, FlatIsTheElementMean) {
  const RadiosityMesh mesh = gridMesh(3, true, 0.2, quadraticField, 3);
  const auto flat = makeInterpolant(mesh, Method::Flat);
  forPointsOf(mesh, [&](uint32_t e, const Vec3& x) {
    const Sample s = flat->evaluate(e, x);
    EXPECT_EQ(s.B, mesh.meanB(e));
    EXPECT_EQ(s.gradient[0], Vec3(0.0));
  });
}

TEST(ElementMethods, LinearAndBilinearReproduceLinearDataWithItsGradient) {
  for (bool quads : {false, true}) {
    const RadiosityMesh mesh = gridMesh(6, quads, 0.3, linearField, 4);
    for (Method method : {Method::Gouraud, Method::Bilinear})
      for (QuadDiagonal diagonal : {QuadDiagonal::D02, QuadDiagonal::D13}) {
        InterpolantOptions options;
        options.diagonal = diagonal;
        const auto interpolant = makeInterpolant(mesh, method, options);
        forPointsOf(mesh, [&](uint32_t e, const Vec3& x) {
          const Sample s = interpolant->evaluate(e, x);
          EXPECT_NEAR(glm::length(s.B - linearField(plane.coords(x))), 0.0, 1e-13);
          for (int c = 0; c < 3; ++c) EXPECT_NEAR(glm::length(s.gradient[c] - linearGradient(c)), 0.0, 1e-11);
        });
      }
  }
}

TEST(ElementMethods, TheTwoQuadDiagonalsDisagreeAndBilinearIsBetweenThem) {
  // C&W fig. 9.7: one quad, values 0.9 0.1 0.7 0.3; the centre is 0.8 along diagonal 0-2,
  // 0.2 along 1-3, and 0.5 bilinearly.
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"m", Rgb(0.5), Rgb(0.0)});
  const double values[4] = {0.9, 0.1, 0.7, 0.3};
  const Vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) mesh.nodes.push_back({plane.at(corners[i].x, corners[i].y), Rgb(values[i]), {}});
  mesh.elements.push_back(Element{{0, 1, 2, 3}, {}, 0, 0});
  const Vec3 centre = plane.at(0.5, 0.5);
  InterpolantOptions d13;
  d13.diagonal = QuadDiagonal::D13;
  EXPECT_NEAR(makeInterpolant(mesh, Method::Gouraud)->evaluate(0, centre).B.r, 0.8, 1e-15);
  EXPECT_NEAR(makeInterpolant(mesh, Method::Gouraud, d13)->evaluate(0, centre).B.r, 0.2, 1e-15);
  EXPECT_NEAR(makeInterpolant(mesh, Method::Bilinear)->evaluate(0, centre).B.r, 0.5, 1e-15);
}

TEST(ElementMethods, BilinearIsTheSameWhicheverCornerComesFirst) {
  const RadiosityMesh mesh = gridMesh(4, true, 0.3, quadraticField, 5);
  RadiosityMesh rotated = mesh;
  for (Element& e : rotated.elements) std::rotate(e.corners.begin(), e.corners.begin() + 1, e.corners.end());
  const auto a = makeInterpolant(mesh, Method::Bilinear), b = makeInterpolant(rotated, Method::Bilinear);
  forPointsOf(mesh, [&](uint32_t e, const Vec3& x) {
    EXPECT_NEAR(glm::length(a->evaluate(e, x).B - b->evaluate(e, x).B), 0.0, 1e-13);
  });
}

TEST(ElementMethods, QuadraticLagrangeReproducesQuadraticsOnTrianglesAndParallelograms) {
  const RadiosityMesh triangles = test::withMidEdgeNodes(gridMesh(4, false, 0.3, quadraticField, 6), quadraticField);
  // Serendipity quads reproduce quadratics where the bilinear map is affine: parallelograms.
  const RadiosityMesh quads = test::withMidEdgeNodes(gridMesh(4, true, 0.0, quadraticField, 7), quadraticField);
  for (const RadiosityMesh* mesh : {&triangles, &quads}) {
    const auto quadratic = makeInterpolant(*mesh, Method::Quadratic);
    forPointsOf(*mesh, [&](uint32_t e, const Vec3& x) {
      const Sample s = quadratic->evaluate(e, x);
      EXPECT_NEAR(glm::length(s.B - quadraticField(plane.coords(x))), 0.0, 1e-13);
      // d/dx of channel 0 (x^2 - 2xy + y^2/2) is 2x - 2y, d/dy is -2x + y.
      const Vec2 p = plane.coords(x);
      const Vec3 want = (2 * p.x - 2 * p.y) * plane.u + (-2 * p.x + p.y) * plane.v;
      EXPECT_NEAR(glm::length(s.gradient[0] - want), 0.0, 1e-11);
    });
  }
}

TEST(ElementMethods, UnknownMethodNameIsAnError) { EXPECT_THROW(methodFromName("cubic"), Error); }

}  // namespace
}  // namespace radview
