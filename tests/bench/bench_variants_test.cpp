// The rows `radview bench` measures, read from the method registry.
#include "bench/bench_variants.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace radview {
namespace {

constexpr int kAdaptive = -1;

TEST(BenchVariants, EveryMethodPerPixelAndThePiecesAtEveryLevelAndTolerance) {
  const std::vector<BenchVariant> variants = benchVariants({2, 8}, {0.5}, false, kAdaptive);
  std::map<Method, int> rows;
  for (const BenchVariant& v : variants) {
    ++rows[v.method];
    EXPECT_TRUE(v.relaxed) << "no C0 edges: nothing to drop";
  }
  // Thin-plate's pieces are Clough-Tocher's: only its values differ, measured per pixel.
  for (const MethodInfo& info : methodRegistry())
    EXPECT_EQ(rows[info.method], info.bezierPieces() && info.method != Method::ThinPlate ? 4 : 1)
        << info.name << ": per pixel, 2 levels, 1 tolerance";
  EXPECT_EQ(variants.front().setting, "per pixel");
  const BenchVariant& adaptive =
      variants[size_t(std::find_if(variants.begin(), variants.end(),
                                   [](const BenchVariant& v) { return v.tessellation == kAdaptive; }) -
                      variants.begin())];
  EXPECT_EQ(adaptive.setting, "adaptive 0.5");
  EXPECT_EQ(adaptive.method, Method::Quadratic) << "registry order";
}

TEST(BenchVariants, C1MethodsAreAlsoMeasuredWithoutRelaxationWhereTheMeshHasC0Edges) {
  size_t unrelaxed = 0;
  for (const BenchVariant& v : benchVariants({4}, {}, true, kAdaptive)) {
    if (v.relaxed) continue;
    ++unrelaxed;
    EXPECT_TRUE(methodInfo(v.method).c1) << methodName(v.method);
    EXPECT_NE(v.setting.find(", C0 not relaxed"), std::string::npos) << v.setting;
  }
  EXPECT_EQ(unrelaxed, 4u) << "c1-quadratic and clough-tocher, per pixel and level 4";
}

}  // namespace
}  // namespace radview
