// The subdivision's estimate of linear interpolation's error (solve/interpolation_error.h), on
// grids of triangles holding functions whose error is known, and the splits it asks for.
#include "solve/interpolation_error.h"

#include "core/display_transform.h"
#include "mesh/solution_file.h"
#include "solve/adaptive_subdivision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

namespace radview {
namespace {

// An n x n grid of unit squares on z = 0, each cut into two triangles by the same diagonal,
// with B = f(x, y) grey at every node.
RadiosityMesh gridOf(int n, const std::function<double(double, double)>& f) {
  RadiosityMesh mesh;
  mesh.materials = {{"grey", Rgb(0.5), Rgb(0.0)}};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.nodes.push_back(Node{Vec3(i, j, 0), Rgb(f(i, j))});
  auto at = [n](int i, int j) { return uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.elements.push_back({{at(i, j), at(i + 1, j), at(i, j + 1)}, {}, 0, 0});
      mesh.elements.push_back({{at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, {}, 0, 0});
    }
  return mesh;
}

// The elements none of whose corners is on the grid's border, where a node's neighbours lie
// on every side and the fitted gradient of a quadratic is exact.
std::vector<uint32_t> interiorElements(const RadiosityMesh& mesh, int n) {
  std::vector<uint32_t> interior;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    bool inside = true;
    for (uint32_t node : mesh.elements[e].corners) {
      const Vec3& p = mesh.nodes[node].position;
      inside &= p.x > 0.5 && p.x < n - 0.5 && p.y > 0.5 && p.y < n - 0.5;
    }
    if (inside) interior.push_back(e);
  }
  return interior;
}

TEST(InterpolationErrorTest, LinearRadiosityHasNoError) {
  const RadiosityMesh mesh = gridOf(6, [](double x, double y) { return 1.0 + 0.3 * x - 0.1 * y; });
  for (double error : relativeInterpolationErrors(mesh, 1e-3)) EXPECT_LT(error, 1e-9);
}

TEST(InterpolationErrorTest, QuadraticRadiosityGivesTheLinearInterpolantsErrorAtTheCentre) {
  constexpr int n = 8;
  auto f = [](double x, double y) { return 3.0 - 0.04 * ((x - 4.0) * (x - 4.0) + (y - 3.0) * (y - 3.0)); };
  const RadiosityMesh mesh = gridOf(n, f);
  const std::vector<double> errors = relativeInterpolationErrors(mesh, 1e-3);
  const std::vector<uint32_t> interior = interiorElements(mesh, n);
  ASSERT_GT(interior.size(), 50u);
  for (uint32_t e : interior) {
    Vec3 c(0.0);
    double linear = 0.0;
    for (uint32_t node : mesh.elements[e].corners) {
      c += mesh.nodes[node].position / 3.0;
      linear += mesh.nodes[node].B.r / 3.0;
    }
    const double expected = std::abs(f(c.x, c.y) - linear) / linear;  // grey: Y = B
    EXPECT_NEAR(errors[e], expected, 1e-6 * expected) << "element " << e;
  }
}

TEST(InterpolationErrorTest, DarkElementsAreMeasuredAgainstTheFloor) {
  auto f = [](double x, double y) { return 1e-4 * (1.0 + 0.5 * (x * x + y * y)); };
  const RadiosityMesh mesh = gridOf(4, f);
  const std::vector<double> relative = relativeInterpolationErrors(mesh, 1e-9);
  const std::vector<double> floored = relativeInterpolationErrors(mesh, 1.0);
  for (size_t e = 0; e < relative.size(); ++e) {
    double linear = 0.0;
    for (uint32_t node : mesh.elements[e].corners) linear += mesh.nodes[node].B.r / 3.0;
    // The same absolute error, over the floor 1 rather than over B.
    EXPECT_NEAR(floored[e], relative[e] * linear, 1e-9 * relative[e]) << "element " << e;
    EXPECT_GT(relative[e], 0.0);
  }
}

// A bright, gently curved floor: its corners differ by less than a display step, so the
// spread criterion splits nothing, while the interpolant sags by about 0.1 % of B.
TEST(InterpolationErrorTest, SubdivisionSplitsCurvedElementsTheSpreadMisses) {
  constexpr int n = 8;
  auto f = [](double x, double y) { return 1.0 - 0.0025 * ((x - 4.0) * (x - 4.0) + (y - 4.0) * (y - 4.0)); };
  const RadiosityMesh mesh = gridOf(n, f);
  SubdivisionCriteria criteria;
  criteria.tolerance = 8.0;
  criteria.maxElements = 100000;
  EXPECT_TRUE(elementsToSplit(mesh, criteria).empty());
  const std::vector<double> errors = relativeInterpolationErrors(mesh, 0.01 / toneMapScale(mesh));
  const double largest = *std::max_element(errors.begin(), errors.end());
  ASSERT_GT(largest, 5e-4);
  criteria.relativeError = 0.5 * largest;
  const std::vector<uint32_t> chosen = elementsToSplit(mesh, criteria);
  ASSERT_FALSE(chosen.empty());
  for (uint32_t e = 0; e < errors.size(); ++e) {
    const bool isChosen = std::find(chosen.begin(), chosen.end(), e) != chosen.end();
    EXPECT_EQ(isChosen, errors[e] > criteria.relativeError) << "element " << e;
  }
  // The largest excess first.
  EXPECT_EQ(errors[chosen.front()], largest);
}

}  // namespace
}  // namespace radview
