// Meshing for the view (C&W §9.3): what a view sees of a mesh, that subdivision splits only
// that, bad views, and that a view-driven solve is still a radiosity solve (furnace, energy).
#include "solve/view_importance.h"

#include "mesh/uniform_mesher.h"
#include "solve/radiosity_solve.h"
#include "tests/solve/cornell_box.h"
#include "tests/solve/solver_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numeric>

namespace radview {
namespace {

SolveView view(const Vec3& eye, const Vec3& target, const std::string& name, double yfovDegrees = 50.0) {
  SolveView v;
  v.camera.eye = eye;
  v.camera.target = target;
  v.camera.yfov = glm::radians(yfovDegrees);
  v.width = 160;
  v.height = 120;
  v.name = name;
  return v;
}

// From inside the box, low over the floor, into the back right corner (green wall, back wall,
// floor): the ceiling, the light, the left wall and the front of the blocks are out of view.
SolveView cornerView() { return view({200, 300, 250}, {0, 50, 559}, "corner"); }

enum Surface { kFloor = 0, kLight = 1, kCeiling = 2, kBackWall = 3, kRightWall = 4, kLeftWall = 5 };

// Elements per scene polygon.
std::vector<size_t> elementsPerSurface(const RadiosityMesh& mesh, size_t surfaces) {
  std::vector<size_t> count(surfaces, 0);
  for (const Element& e : mesh.elements) ++count[size_t(e.surface)];
  return count;
}

SolveSettings cornellSettings(size_t maxElements) {
  SolveSettings settings;
  settings.patchSize = 100.0;
  settings.solver.stopUnshotFraction = 0.05;
  settings.subdivision.tolerance = 2.0;
  settings.subdivision.minElementSize = 6.0;
  settings.subdivision.maxElements = maxElements;
  return settings;
}

TEST(ViewDrivenTest, PixelsCountOnlyFrontSidesInView) {
  const Scene scene = test::cornellBox();
  const RadiosityMesh mesh = meshUniformly(scene, 100.0);
  const SolveView corner = cornerView();
  const std::vector<uint32_t> pixels = viewedPixels(mesh, {corner});
  std::vector<uint32_t> perSurface(scene.polygons.size(), 0);
  for (size_t e = 0; e < mesh.elements.size(); ++e) perSurface[size_t(mesh.elements[e].surface)] += pixels[e];
  EXPECT_GT(perSurface[kFloor], 0u);
  EXPECT_GT(perSurface[kBackWall], 0u);
  EXPECT_GT(perSurface[kRightWall], 0u);
  EXPECT_EQ(perSurface[kCeiling], 0u);
  EXPECT_EQ(perSurface[kLight], 0u);
  EXPECT_EQ(perSurface[kLeftWall], 0u);
  // Every pixel sees the box from inside: each counts once, for the element it sees.
  EXPECT_EQ(std::accumulate(pixels.begin(), pixels.end(), size_t(0)), size_t(corner.width) * corner.height);
  // Two views add up.
  const std::vector<uint32_t> twice = viewedPixels(mesh, {corner, corner});
  for (size_t e = 0; e < mesh.elements.size(); ++e) EXPECT_EQ(twice[e], 2 * pixels[e]);

  // Behind the back wall, looking in: the wall's back fills the view and counts for nothing.
  const SolveView behind = view({278, 273, 1500}, {278, 273, 0}, "behind", 30.0);
  const std::vector<uint32_t> none = viewedPixels(mesh, {behind});
  EXPECT_EQ(std::accumulate(none.begin(), none.end(), size_t(0)), 0u);
}

TEST(ViewDrivenTest, ViewsThatSeeNoFrontSideAreLeftOutWithTheirReason) {
  const RadiosityMesh mesh = meshUniformly(test::cornellBox(), 100.0);
  const UsableViews usable = usableViews(mesh, {view({278, 273, -800}, {278, 273, -1600}, "away"), cornerView(),
                                                view({370, 150, 350}, {278, 273, 0}, "inside the tall block"),
                                                view({278, 273, 1500}, {278, 273, 0}, "behind")});
  ASSERT_EQ(usable.views.size(), 1u);
  EXPECT_EQ(usable.views[0].name, "corner");
  ASSERT_EQ(usable.warnings.size(), 3u);
  EXPECT_EQ(usable.warnings[0], "view 'away' (eye 278,273,-800) sees nothing of the scene; it is left out");
  EXPECT_NE(usable.warnings[1].find("view 'inside the tall block' (eye 370,150,350) sees only the backs of surfaces"),
            std::string::npos)
      << usable.warnings[1];
  EXPECT_NE(usable.warnings[1].find("its eye is inside a solid or behind a wall; it is left out"), std::string::npos);
  EXPECT_NE(usable.warnings[2].find("view 'behind'"), std::string::npos);
}

TEST(ViewDrivenTest, OnlyElementsInViewAreSplit) {
  RadiosityMesh mesh = meshUniformly(test::cornellBox(), 100.0);
  // A spread on every element: its first corner bright, the rest dark.
  for (const Element& e : mesh.elements) mesh.nodes[e.corners[0]].B = Rgb(1.0);
  SubdivisionCriteria criteria;
  criteria.views = {cornerView()};
  const std::vector<uint32_t> pixels = viewedPixels(mesh, criteria.views);
  const std::vector<uint32_t> chosen = elementsToSplit(mesh, criteria);
  ASSERT_FALSE(chosen.empty());
  for (uint32_t e : chosen) EXPECT_GT(pixels[e], 0u) << "element " << e;
  // Without the view, elements out of it are chosen too.
  criteria.views.clear();
  size_t unseen = 0;
  for (uint32_t e : elementsToSplit(mesh, criteria)) unseen += pixels[e] == 0;
  EXPECT_GT(unseen, 0u);
}

TEST(ViewDrivenTest, ElementsNoViewSeesAreNeverRefinedAndTheBudgetGoesWhereItShows) {
  const Scene scene = test::cornellBox();
  const SolveView corner = cornerView();
  SolveSettings settings = cornellSettings(4000);
  const RadiosityMesh initial = initialMesh(scene, resolvedFor(scene, settings), nullptr);
  SolveSummary independentSummary, drivenSummary;
  const RadiosityMesh independent = solveRadiosity(scene, settings, independentSummary);
  settings.subdivision.views = {corner};
  const RadiosityMesh driven = solveRadiosity(scene, settings, drivenSummary);
  EXPECT_EQ(drivenSummary.views, 1u);
  EXPECT_TRUE(drivenSummary.viewWarnings.empty());
  validateMesh(driven, "view-driven Cornell");

  const size_t surfaces = scene.polygons.size();
  const std::vector<size_t> before = elementsPerSurface(initial, surfaces);
  const std::vector<size_t> afterIndependent = elementsPerSurface(independent, surfaces);
  const std::vector<size_t> afterDriven = elementsPerSurface(driven, surfaces);
  std::vector<uint32_t> seenPerSurface(surfaces, 0);
  const std::vector<uint32_t> pixels = viewedPixels(initial, {corner});
  for (size_t e = 0; e < initial.elements.size(); ++e) seenPerSurface[size_t(initial.elements[e].surface)] += pixels[e];
  size_t unseenRefinedIndependently = 0;
  for (size_t s = 0; s < surfaces; ++s) {
    if (seenPerSurface[s] > 0) continue;
    EXPECT_EQ(afterDriven[s], before[s]) << "surface " << s << " is out of view";
    unseenRefinedIndependently += afterIndependent[s] > before[s];
  }
  EXPECT_GE(unseenRefinedIndependently, 2u) << "the view-independent solve refines surfaces out of view";
  EXPECT_GT(afterDriven[kRightWall], afterIndependent[kRightWall]);

  // What the budget buys: the elements the view sees at the end.
  auto seenElements = [&](const RadiosityMesh& mesh) {
    size_t seen = 0;
    for (uint32_t p : viewedPixels(mesh, {corner})) seen += p > 0;
    return seen;
  };
  const size_t seenIndependent = seenElements(independent), seenDriven = seenElements(driven);
  std::printf("corner view, budget 4000: view-independent %zu elements, %zu seen; view-driven %zu, %zu seen\n",
              independent.elements.size(), seenIndependent, driven.elements.size(), seenDriven);
  EXPECT_GT(seenDriven, 2 * seenIndependent);
}

TEST(ViewDrivenTest, ASolveWhoseViewsSeeNothingIsTheViewIndependentOne) {
  const Scene scene = test::cornellBox();
  SolveSettings settings = cornellSettings(1500);
  SolveSummary plainSummary, badSummary;
  const RadiosityMesh plain = solveRadiosity(scene, settings, plainSummary);
  settings.subdivision.views = {view({278, 273, -800}, {278, 273, -1600}, "away"),
                                view({370, 150, 350}, {278, 273, 0}, "inside")};
  const RadiosityMesh bad = solveRadiosity(scene, settings, badSummary);
  EXPECT_EQ(badSummary.views, 0u);
  ASSERT_EQ(badSummary.viewWarnings.size(), 3u);
  EXPECT_EQ(badSummary.viewWarnings[2], "no view sees the scene: the subdivision is view-independent");
  ASSERT_EQ(bad.elements.size(), plain.elements.size());
  ASSERT_GT(bad.elements.size(), plainSummary.progress.patches);
  ASSERT_EQ(bad.nodes.size(), plain.nodes.size());
  for (size_t i = 0; i < bad.nodes.size(); ++i)
    EXPECT_EQ(std::memcmp(&bad.nodes[i].B, &plain.nodes[i].B, sizeof(Rgb)), 0) << "node " << i;
}

TEST(ViewDrivenTest, FurnaceStillConvergesToEOverOneMinusRho) {
  // As ProgressiveRefinementTest's furnace, solved with subdivision for a view from the middle
  // of the box onto one face: B = E / (1 - rho) = 2 at every node, split or not.
  const Scene scene = test::furnaceBox(Rgb(0.5), Rgb(1.0));
  SolveSettings settings;
  settings.patchSize = 0.25;
  settings.solver.stopUnshotFraction = 1e-4;
  settings.subdivision.tolerance = 0.01;
  settings.subdivision.maxElements = 400;
  settings.subdivision.views = {view({0.5, 0.5, 0.5}, {0.5, 0.5, 0.0}, "inside", 60.0)};
  SolveSummary summary;
  const RadiosityMesh mesh = solveRadiosity(scene, settings, summary);
  EXPECT_EQ(summary.views, 1u);
  double worst = 0.0;
  for (const Node& node : mesh.nodes)
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(node.B[k] - 2.0));
  EXPECT_LT(worst, 0.005) << "largest |B - 2|";
}

TEST(ViewDrivenTest, ClosedCornellBoxStillBalancesEnergy) {
  // As ProgressiveRefinementTest's energy balance (50 mm patches: +2.3..2.9 % measured without
  // subdivision), with elements split for a view inside the closed box.
  Scene scene = test::closedCornellBox();
  SolveSettings settings = cornellSettings(5000);
  settings.patchSize = 50.0;
  settings.solver.stopUnshotFraction = 0.01;
  settings.subdivision.views = {view({278, 273, 50}, {278, 273, 559}, "inside")};
  SolveSummary summary;
  const RadiosityMesh mesh = solveRadiosity(scene, settings, summary);
  EXPECT_EQ(summary.views, 1u);
  EXPECT_GT(mesh.elements.size(), 2 * summary.progress.patches);
  const EnergyBalance& energy = summary.energy;
  for (int k = 0; k < 3; ++k) {
    const double residual = (energy.emitted[k] - energy.absorbed[k] - energy.unshot[k]) / energy.emitted[k];
    std::printf("closed Cornell box, view-driven, channel %d: (emitted - absorbed - unshot) / emitted = %+.4f\n", k,
                residual);
    EXPECT_LT(std::abs(residual), 0.04) << "channel " << k;
  }
}

}  // namespace
}  // namespace radview
