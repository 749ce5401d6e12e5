// The viewer's background solve takes the same steps as `radview solve` (solveRadiosity): the
// same settings give the same mesh, bit for bit, and a cancelled solve stops between steps.
#include "solve/background_solve.h"

#include "solve/radiosity_solve.h"
#include "tests/solve/cornell_box.h"
#include "tests/test_print.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace radview {
namespace {

// Coarse, with subdivision, so that both phases run in about a second.
SolveSettings smallSolve() {
  SolveSettings settings;
  settings.patchSize = 100.0;
  settings.solver.stopUnshotFraction = 0.05;
  settings.subdivision.minElementSize = 25.0;
  settings.subdivision.maxElements = 800;
  return settings;
}

RadiosityMesh waitForTheLastSolution(BackgroundSolve& solve) {
  std::optional<RadiosityMesh> last;
  while (solve.running()) {
    if (std::optional<RadiosityMesh> mesh = solve.takeSolution()) last = std::move(mesh);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (std::optional<RadiosityMesh> mesh = solve.takeSolution()) last = std::move(mesh);
  EXPECT_TRUE(last.has_value()) << "nothing was published";
  return last ? *last : RadiosityMesh{};
}

TEST(BackgroundSolve, GivesTheMeshRadviewSolveWrites) {
  const Scene scene = test::cornellBox();
  SolveSummary summary;
  const RadiosityMesh direct = solveRadiosity(scene, smallSolve(), summary);
  ASSERT_GT(summary.subdivisionRounds, 0) << "the test needs both phases";
  BackgroundSolve solve;
  solve.start(scene, smallSolve());
  const RadiosityMesh background = waitForTheLastSolution(solve);
  EXPECT_EQ(solve.status().rfind("solved: ", 0), 0u) << solve.status();
  ASSERT_EQ(background.nodes.size(), direct.nodes.size());
  ASSERT_EQ(background.elements.size(), direct.elements.size());
  for (size_t i = 0; i < direct.nodes.size(); ++i) {
    ASSERT_EQ(background.nodes[i].position, direct.nodes[i].position) << "node " << i;
    ASSERT_EQ(background.nodes[i].B, direct.nodes[i].B) << "node " << i;
  }
  for (size_t e = 0; e < direct.elements.size(); ++e)
    ASSERT_EQ(background.elements[e].corners, direct.elements[e].corners) << "element " << e;
}

TEST(BackgroundSolve, WithoutSubdivisionItStopsAfterShootingAsSolveRadiosityDoes) {
  SolveSettings settings = smallSolve();
  settings.subdivide = false;
  const Scene scene = test::cornellBox();
  SolveSummary summary;
  const RadiosityMesh direct = solveRadiosity(scene, settings, summary);
  BackgroundSolve solve;
  solve.start(scene, settings);
  EXPECT_EQ(waitForTheLastSolution(solve).elements.size(), direct.elements.size());
}

TEST(BackgroundSolve, CancelledItStopsBetweenStepsWithWhatItHas) {
  SolveSettings settings = smallSolve();
  settings.solver.stopUnshotFraction = 0.0;  // would shoot to maxShots
  settings.solver.maxShots = 100000;
  BackgroundSolve solve;
  solve.start(test::cornellBox(), settings);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  solve.cancel();
  EXPECT_FALSE(solve.running());
  EXPECT_EQ(solve.status().rfind("cancelled: ", 0), 0u) << solve.status();
  EXPECT_TRUE(solve.takeSolution().has_value());
}

}  // namespace
}  // namespace radview
