// The limits' one message form, and the relations between limits that the code relies on.
#include "core/limits.h"

#include "core/error.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

TEST(Limits, PastALimitTheErrorNamesTheSourceTheValueAndTheLimit) {
  EXPECT_NO_THROW(checkLimit("scene.glb", 100, 100, "nodes"));
  try {
    checkLimit("scene.glb", 3000000000, 16000000, "nodes");
    ADD_FAILURE() << "no Error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "scene.glb: 3000000000 nodes, more than radview's limit of 16000000");
  }
}

TEST(Limits, EveryFileRadviewWritesItCanRead) {
  // The solver and meshers make at most kMaxMeshElements; T-vertex triangulation may multiply
  // them, and the solution file limits leave room for that.
  static_assert(kMaxSolutionElements >= kMaxMeshElements);
  static_assert(kMaxSolutionNodes >= kMaxSolutionElements);
  static_assert(kMaxStoredVertices >= kMaxSolutionNodes);
  // Every accessor of a solution at the limits fits the accessor limit.
  static_assert(kMaxAccessorElements >= kMaxStoredVertices);
  static_assert(kMaxSceneTriangles <= kMaxAccessorElements);
}

}  // namespace
}  // namespace radview
