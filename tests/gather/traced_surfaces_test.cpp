// What the ray tracers take from an opened file (gather/traced_surfaces.h).
#include "gather/traced_surfaces.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <string>

namespace radview {
namespace {

const std::string kScene = RADVIEW_SOURCE_DIR "/assets/cornell_box.gltf";
const std::string kSolution = RADVIEW_SOURCE_DIR "/assets/fig9_8_quad.gltf";

TEST(TracedSurfaces, AScenesOwnPolygonsOrASolutionsElements) {
  const ViewedFile scene = openForViewing(kScene, 0.1, {}, kDirectLight);
  EXPECT_EQ(tracedSurfaces(scene).polygons.size(), scene.file.scene.polygons.size());
  const ViewedFile solution = openForViewing(kSolution, 0.0, {}, kDirectLight);
  EXPECT_EQ(tracedSurfaces(solution).polygons.size(), solution.mesh.elements.size());
}

TEST(TracedSurfaces, TheFinalGatherRefusesDirectLightAloneAndThePathTracerDoesNot) {
  const ViewedFile viewed = openForViewing(kScene, 0.1, {}, kDirectLight);
  EXPECT_NO_THROW(checkRayTracingRuns(viewed, "the path tracer"));
  try {
    checkRayTracingRuns(viewed, "the final gather");
    FAIL() << "the gather over direct light alone should be refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(kScene + ": the final gather cannot run with --direct-only"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace radview
