// The thin-plate smoothing spline (interp/thin_plate.h) against what it must do: keep linear data
// for every lambda, give back the data at lambda 0, take noise off a smooth function by the
// factor its effective degrees of freedom predict, keep a step across a C-1 edge and a kink
// along a C0 edge, and refuse bad weights.
#include "interp/thin_plate.h"

#include "core/error.h"
#include "tests/interp/test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace radview {
namespace {

using test::gridMesh;
using test::Plane;

double largestDifference(const RadiosityMesh& a, const RadiosityMesh& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.nodes.size(); ++i)
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a.nodes[i].B[c] - b.nodes[i].B[c]));
  return worst;
}

RadiosityMesh smoothed(const RadiosityMesh& mesh, std::optional<double> lambda, ThinPlateReport* report = nullptr) {
  ThinPlateSettings settings;
  settings.lambda = lambda;
  return smoothThinPlate(mesh, MeshTopology(mesh), settings, report);
}

TEST(ThinPlateTest, LinearDataAreKeptForEveryLambda) {
  const Plane plane;
  for (bool quads : {false, true}) {
    const RadiosityMesh mesh = gridMesh(
        12, quads, 0.3, [](const Vec2& p) { return Rgb(0.2 + 0.5 * p.x - 0.3 * p.y, 0.4 + p.y, 1.0 - p.x); }, 7, plane);
    for (std::optional<double> lambda : {std::optional<double>(0.0), std::optional<double>(1e-6),
                                         std::optional<double>(1.0), std::optional<double>(1e3), std::optional<double>()})
      EXPECT_LT(largestDifference(smoothed(mesh, lambda), mesh), 1e-8)
          << (quads ? "quads" : "triangles") << ", lambda " << (lambda ? *lambda : -1.0);
  }
}

TEST(ThinPlateTest, LambdaZeroGivesTheDataAndASmallOneAlmostThem) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> value(0.0, 1.0);
  RadiosityMesh mesh = gridMesh(10, false, 0.3, [](const Vec2&) { return Rgb(0.0); }, 5);
  for (Node& node : mesh.nodes) node.B = Rgb(value(random), value(random), value(random));
  EXPECT_EQ(largestDifference(smoothed(mesh, 0.0), mesh), 0.0);
  EXPECT_LT(largestDifference(smoothed(mesh, 1e-12), mesh), 1e-6);
  EXPECT_GT(largestDifference(smoothed(mesh, 1.0), mesh), 0.1) << "a real lambda smooths random data";
}

// Noisy samples of a smooth function: the fit's error against the function is the noise times
// about sqrt(dof / n) (for a linear smoother A the noise left is sigma^2 tr(A^2) / n <= sigma^2
// tr(A) / n, and the bias of a smooth function is small), and far below the noise itself.
TEST(ThinPlateTest, NoiseOnASmoothFunctionShrinksAsItsDegreesOfFreedomSay) {
  auto smooth = [](const Vec2& p) {
    const double v = 0.5 + 0.3 * std::sin(2.0 * p.x) * std::cos(1.5 * p.y);
    return Rgb(v, 0.8 * v, 0.6 * v);
  };
  const RadiosityMesh truth = gridMesh(40, false, 0.3, smooth, 11);
  RadiosityMesh noisy = truth;
  std::mt19937 random(19);
  const double sigma = 0.05;
  std::normal_distribution<double> noise(0.0, sigma);
  for (Node& node : noisy.nodes) node.B += Rgb(noise(random));
  ThinPlateReport report;
  const RadiosityMesh fit = smoothed(noisy, std::nullopt, &report);
  ASSERT_EQ(report.regions.size(), 1u);
  double squares = 0.0;
  for (size_t i = 0; i < fit.nodes.size(); ++i) {
    const double d = fit.nodes[i].B.r - truth.nodes[i].B.r;
    squares += d * d / double(fit.nodes.size());
  }
  const double factor = std::sqrt(squares) / sigma;
  const double predicted = std::sqrt(report.regions[0].effectiveDof / double(fit.nodes.size()));
  std::printf("%zu nodes: lambda %.3g, %.1f degrees of freedom; error / noise %.3f, sqrt(dof / n) %.3f\n",
              fit.nodes.size(), report.regions[0].lambda, report.regions[0].effectiveDof, factor, predicted);
  EXPECT_LT(factor, 0.3);
  EXPECT_GT(factor, 0.4 * predicted);
  EXPECT_LT(factor, 1.5 * predicted);
}

// A region above 12,000 nodes is cross-validated in pieces (thin_plate_region.h): its lambda
// must still be the one that serves it best, within 10 %, among the decades around it.
TEST(ThinPlateTest, LambdaChosenInPiecesServesTheWholeRegion) {
  auto smooth = [](const Vec2& p) {
    const double v = 0.5 + 0.3 * std::sin(3.0 * p.x) * std::cos(2.5 * p.y);
    return Rgb(v, 0.8 * v, 0.6 * v);
  };
  const RadiosityMesh truth = gridMesh(190, false, 0.3, smooth, 5);  // 36,481 nodes
  RadiosityMesh noisy = truth;
  std::mt19937 random(23);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (Node& node : noisy.nodes) node.B += Rgb(noise(random));
  auto error = [&](const RadiosityMesh& fit) {
    double squares = 0.0;
    for (size_t i = 0; i < fit.nodes.size(); ++i) squares += std::pow(fit.nodes[i].B.r - truth.nodes[i].B.r, 2);
    return std::sqrt(squares / double(fit.nodes.size()));
  };
  ThinPlateReport report;
  const double chosen = error(smoothed(noisy, std::nullopt, &report));
  ASSERT_EQ(report.regions.size(), 1u);
  ASSERT_TRUE(report.regions[0].smoothed);
  const double lambda = report.regions[0].lambda;
  double best = chosen;
  for (double decade : {0.01, 0.1, 10.0, 100.0}) {
    const double e = error(smoothed(noisy, lambda * decade));
    std::printf("lambda %.3g: error %.4g\n", lambda * decade, e);
    best = std::min(best, e);
  }
  std::printf("%zu nodes: chosen lambda %.3g, error %.4g; best of the decades around it %.4g\n",
              noisy.nodes.size(), lambda, chosen, best);
  EXPECT_LE(chosen, 1.1 * best);
  EXPECT_LT(chosen, 0.3 * 0.05);
}

// Without standard errors, cross-validation alone judges what is noise: exact values are kept,
// in a small region (too few nodes to judge) and in a large one (no noise found: the best
// lambda is the least one the score allows).
TEST(ThinPlateTest, ExactValuesWithoutStandardErrorsAreKept) {
  auto curved = [](const Vec2& p) { return Rgb(0.3 + 0.4 * p.x * p.x + 0.2 * std::sin(3.0 * p.y)); };
  for (int n : {6, 30}) {
    const RadiosityMesh mesh = gridMesh(n, false, 0.3, curved, 9);
    EXPECT_EQ(largestDifference(smoothed(mesh, std::nullopt), mesh), 0.0) << (n + 1) * (n + 1) << " nodes";
  }
}

// Two halves of a unit square, each its own nodes along x = 0.5, valued 1 and 0 with noise.
RadiosityMesh twoHalves(bool cMinus1) {
  RadiosityMesh mesh = gridMesh(16, false, 0.0, [](const Vec2& p) { return Rgb(p.x < 0.5 + 1e-9 ? 1.0 : 0.0); }, 2);
  const Plane plane;
  if (cMinus1) {
    // The right half's elements get their own copies of the nodes on the seam.
    std::vector<uint32_t> copyOf(mesh.nodes.size(), UINT32_MAX);
    for (Element& e : mesh.elements) {
      Vec3 centre(0.0);
      for (uint32_t n : e.corners) centre += mesh.nodes[n].position / 3.0;
      if (plane.coords(centre).x < 0.5) continue;
      for (uint32_t& n : e.corners)
        if (std::abs(plane.coords(mesh.nodes[n].position).x - 0.5) < 1e-9) {
          if (copyOf[n] == UINT32_MAX) {
            copyOf[n] = uint32_t(mesh.nodes.size());
            Node copy = mesh.nodes[n];
            copy.B = Rgb(0.0);
            mesh.nodes.push_back(copy);
          }
          n = copyOf[n];
        }
    }
  }
  std::mt19937 random(23);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (Node& node : mesh.nodes) node.B += Rgb(noise(random));
  return mesh;
}

TEST(ThinPlateTest, AStepAcrossACm1EdgeStaysAStep) {
  const Plane plane;
  ThinPlateReport report;
  const RadiosityMesh fit = smoothed(twoHalves(true), std::nullopt, &report);
  EXPECT_EQ(report.regions.size(), 2u);
  for (const ThinPlateRegion& r : report.regions)
    std::printf("region of %zu nodes: lambda %.3g, %.2f degrees of freedom\n", r.nodes, r.lambda, r.effectiveDof);
  double worst = 0.0;
  for (const Node& node : fit.nodes) {
    const bool left = node.B.r > 0.5;
    worst = std::max(worst, std::abs(node.B.r - (left ? 1.0 : 0.0)));
  }
  EXPECT_LT(worst, 0.03) << "every fitted value stays with its own side's level";
  // Without the cut, one region: the step is smoothed into a ramp, values near 0.5 appear.
  const RadiosityMesh joined = smoothed(twoHalves(false), 0.1);
  double nearestHalf = 1.0;
  for (const Node& node : joined.nodes) nearestHalf = std::min(nearestHalf, std::abs(node.B.r - 0.5));
  EXPECT_LT(nearestHalf, 0.2);
}

// A roof, |x - 0.5|, with its ridge tagged C0: each side is linear, so the fit keeps the kink
// whatever lambda; untagged, a large lambda flattens it.
TEST(ThinPlateTest, AC0EdgeKeepsItsKink) {
  const Plane plane;
  RadiosityMesh mesh = gridMesh(16, false, 0.0, [](const Vec2& p) { return Rgb(std::abs(p.x - 0.5)); }, 2);
  const RadiosityMesh untagged = mesh;
  std::vector<uint32_t> ridge;
  for (uint32_t n = 0; n < mesh.nodes.size(); ++n)
    if (std::abs(plane.coords(mesh.nodes[n].position).x - 0.5) < 1e-9) ridge.push_back(n);
  std::sort(ridge.begin(), ridge.end(), [&](uint32_t a, uint32_t b) {
    return plane.coords(mesh.nodes[a].position).y < plane.coords(mesh.nodes[b].position).y;
  });
  for (size_t i = 0; i + 1 < ridge.size(); ++i) mesh.discontinuities.push_back({ridge[i], ridge[i + 1], Continuity::C0});
  EXPECT_LT(largestDifference(smoothed(mesh, 1e3), mesh), 1e-9);
  EXPECT_GT(largestDifference(smoothed(untagged, 1e3), untagged), 0.05);
}

TEST(ThinPlateTest, BadWeightsAndLambdasAreRefused) {
  const RadiosityMesh mesh = gridMesh(4, false, 0.0, [](const Vec2& p) { return Rgb(p.x); }, 1);
  const MeshTopology topology(mesh);
  std::vector<double> weights(mesh.nodes.size(), 1.0);
  for (double bad : {std::nan(""), -1.0, double(INFINITY)}) {
    weights[3] = bad;
    try {
      smoothThinPlate(mesh, topology, {}, nullptr, &weights);
      ADD_FAILURE() << "weight " << bad << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("node 3 has weight"), std::string::npos) << e.what();
    }
  }
  weights.pop_back();
  EXPECT_THROW(smoothThinPlate(mesh, topology, {}, nullptr, &weights), Error);
  for (double bad : {-1.0, std::nan("")}) {
    ThinPlateSettings settings;
    settings.lambda = bad;
    EXPECT_THROW(smoothThinPlate(mesh, topology, settings), Error) << bad;
  }
}

}  // namespace
}  // namespace radview
