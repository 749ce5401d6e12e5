#include "solve/direct_light.h"

#include "cornell_box.h"
#include "mesh/uniform_mesher.h"

#include <gtest/gtest.h>

#include <cmath>

namespace radview {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Differential area under the corner of a parallel a x b rectangle at height h, facing it.
double parallelCornerF(double a, double b, double h) {
  const double A = a / h, B = b / h, sA = std::sqrt(1 + A * A), sB = std::sqrt(1 + B * B);
  return (A / sA * std::atan(B / sA) + B / sB * std::atan(A / sB)) / (2 * kPi);
}

// Point under the parallel rectangle [x1, x2] x [z1, z2] (coordinates relative to the point's
// foot) at height h: corner rectangles added and subtracted, each signed by its quadrant.
double parallelRectangleF(double x1, double x2, double z1, double z2, double h) {
  auto corner = [&](double a, double b) {
    return (a < 0 ? -1 : 1) * (b < 0 ? -1 : 1) * parallelCornerF(std::abs(a), std::abs(b), h);
  };
  return corner(x2, z2) - corner(x1, z2) - corner(x2, z1) + corner(x1, z1);
}

// A floor [-1,1]^2 facing +z under a square light [-0.5,0.5]^2 at z = 1 facing -z.
Scene floorUnderSquareLight() {
  Scene scene;
  scene.materials = {{"floor", {0.5, 0.25, 0.125}, {0, 0, 0}}, {"light", {0.8, 0.8, 0.8}, {10, 20, 30}}};
  scene.polygons.push_back({{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, 0});
  scene.polygons.push_back({{{-0.5, -0.5, 1}, {-0.5, 0.5, 1}, {0.5, 0.5, 1}, {0.5, -0.5, 1}}, 1});
  return scene;
}

TEST(DirectLightTest, NodeUnderTheCentreOfASquareEmitterMatchesTheClosedForm) {
  const Scene scene = floorUnderSquareLight();
  const RadiosityMesh mesh = meshAndLight(scene, 0.5);
  const Rgb expected = scene.materials[0].rho * scene.materials[1].E * (4 * parallelCornerF(0.5, 0.5, 1.0));
  int found = 0;
  for (const Node& node : mesh.nodes)
    if (node.position == Vec3(0.0)) {
      ++found;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(node.B[c], expected[c], 1e-14 * expected[c]) << c;
    }
  EXPECT_EQ(found, 1);
}

TEST(DirectLightTest, EmitterNodesKeepTheirEmission) {
  const Scene scene = floorUnderSquareLight();
  const RadiosityMesh mesh = meshAndLight(scene, 0.25);
  int emitterNodes = 0;
  for (const Element& e : mesh.elements)
    if (e.surface == 1)
      for (uint32_t n : e.corners) {
        EXPECT_EQ(mesh.nodes[n].B, scene.materials[1].E);  // it does not light itself
        ++emitterNodes;
      }
  EXPECT_GT(emitterNodes, 0);
}

TEST(DirectLightTest, FacingEmittersLightEachOther) {
  Scene scene = floorUnderSquareLight();
  scene.materials[0].E = {1, 2, 3};  // the floor emits too
  const RadiosityMesh mesh = meshAndLight(scene, 0.5);
  // The light's centre node sees the whole 2 x 2 floor at distance 1.
  const Rgb expected =
      scene.materials[1].E + scene.materials[1].rho * scene.materials[0].E * (4 * parallelCornerF(1, 1, 1));
  int found = 0;
  for (const Node& node : mesh.nodes) {
    if (node.position != Vec3(0, 0, 1)) continue;
    ++found;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(node.B[c], expected[c], 1e-14 * expected[c]);
  }
  EXPECT_EQ(found, 1);
}

// The Cornell box, unoccluded (the blocks cast no shadow here): every floor node under the
// axis-aligned light matches the closed form of a parallel rectangle; the ceiling is behind
// the (lowered) light's plane and gets nothing; nothing is NaN or negative.
TEST(DirectLightTest, CornellBoxFloorMatchesTheClosedFormAndNothingIsNaN) {
  const Scene box = test::cornellBox();
  const RadiosityMesh mesh = meshAndLight(box, defaultElementSize(box));
  const Material& white = box.materials[0];
  const Rgb E = box.materials[3].E;
  double worst = 0.0;
  for (const Element& e : mesh.elements)
    for (uint32_t n : e.corners) {
      const Node& node = mesh.nodes[n];
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(node.B[c]) && node.B[c] >= 0.0) << node;
      if (e.surface == 0) {  // floor, y = 0
        const Vec3 p = node.position;
        const double F = parallelRectangleF(213 - p.x, 343 - p.x, 227 - p.z, 332 - p.z, 548.7);
        for (int c = 0; c < 3; ++c) {
          const double expected = white.rho[c] * E[c] * F;
          worst = std::max(worst, std::abs(node.B[c] - expected) / expected);
          EXPECT_NEAR(node.B[c], expected, 1e-11 * expected) << node;
        }
      }
      if (e.surface == 2) {
        EXPECT_EQ(node.B, Rgb(0.0)) << node;  // ceiling
      } else if (e.surface == 1) {
        EXPECT_EQ(node.B, E) << node;  // light
      }
    }
  std::printf("Cornell floor vs closed form: max relative error %.2e over the floor nodes\n", worst);
}

TEST(DirectLightTest, DefaultElementSizeIsADiagonalOverForty) {
  const Scene box = test::cornellBox();
  EXPECT_DOUBLE_EQ(defaultElementSize(box), box.bounds().diagonal() / 40);
  EXPECT_EQ(defaultElementSize(Scene{}), 1.0);
}

}  // namespace
}  // namespace radview
