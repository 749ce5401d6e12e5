// The limits' one message form (the relations between limits are checked where they are
// defined, core/limits.h, at compile time).
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

}  // namespace
}  // namespace radview
