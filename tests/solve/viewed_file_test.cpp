// Opening a file to be shown (solve/viewed_file.h): a solution as it is, a scene solved with the
// progress reported, or lit by its direct light alone; every error names the file.
#include "solve/viewed_file.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <string>

namespace radview {
namespace {

const std::string kScene = RADVIEW_SOURCE_DIR "/assets/cornell_box.gltf";
const std::string kSolution = RADVIEW_SOURCE_DIR "/assets/fig9_8_quad.gltf";

SceneLightOptions quickSolve() {
  SceneLightOptions light;
  light.solve.solver.maxShots = 20;
  light.solve.subdivide = false;
  return light;
}

TEST(ViewedFile, ASolutionIsShownAsItIs) {
  const ViewedFile viewed = openForViewing(kSolution, 0.0, {}, quickSolve());
  EXPECT_TRUE(viewed.file.isSolution);
  EXPECT_TRUE(viewed.file.mesh.elements.empty()) << "the mesh moves into ViewedFile::mesh, not copied";
  EXPECT_EQ(viewed.mesh.elements.size(), 1u);
  EXPECT_TRUE(viewed.lighting.empty());
  EXPECT_FALSE(viewed.directLightOnly);
}

TEST(ViewedFile, ASceneIsSolvedAndItsProgressReportedToTheEnd) {
  int updates = 0, finished = 0;
  SolveProgress last;
  const ViewedFile viewed =
      openForViewing(kScene, 0.0, {}, quickSolve(), nullptr, [&](const SolveProgress& p, bool done) {
        EXPECT_EQ(finished, 0) << "nothing is reported after the end";
        ++updates;
        finished += done ? 1 : 0;
        last = p;
      });
  EXPECT_EQ(finished, 1);
  EXPECT_GE(updates, 1);
  EXPECT_EQ(last.shots, 20u);
  EXPECT_EQ(last.elements, viewed.mesh.elements.size());
  EXPECT_FALSE(viewed.directLightOnly);
  EXPECT_EQ(viewed.lighting.rfind("radiosity solve: 20 shots", 0), 0u) << viewed.lighting;
  EXPECT_GT(viewed.elementSize, 0.0) << "the solve's patch size";
}

TEST(ViewedFile, DirectOnlyMeshesUniformlyAndSaysSoWithoutSolving) {
  bool reported = false;
  const ViewedFile viewed =
      openForViewing(kScene, 0.05, {}, kDirectLight, nullptr, [&](const SolveProgress&, bool) { reported = true; });
  EXPECT_FALSE(reported);
  EXPECT_TRUE(viewed.directLightOnly);
  EXPECT_EQ(viewed.lighting, kDirectOnlyLabel);
  EXPECT_DOUBLE_EQ(viewed.elementSize, 0.05);
  EXPECT_FALSE(viewed.mesh.elements.empty());
}

TEST(ViewedFile, TheCheckSeesTheFileBeforeAnySolve) {
  bool reported = false;
  try {
    openForViewing(
        kScene, 0.0, {}, quickSolve(), [](const LoadedFile& f) { throw Error(f.path, "refused by the check"); },
        [&](const SolveProgress&, bool) { reported = true; });
    FAIL() << "the check's error should reach the caller";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), kScene + ": refused by the check");
  }
  EXPECT_FALSE(reported);
}

TEST(ViewedFile, ErrorsNameTheFile) {
  SceneLightOptions light = quickSolve();
  light.directOnly = true;
  try {
    openForViewing(kScene, 1e-6, {}, light);  // far more elements than radview meshes
    FAIL() << "a mesh past the limit should be refused";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(kScene + ": ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace radview
