// The final gather (C&W §9.3.1) at numerical extremes (issue 7): the closed box of
// tests/extreme_scenes.h, its ceiling emitting, radiosities 1e-8..1e8 as B^, at every scale and
// distance from the origin, seen from inside. Every pixel finite; every pixel covered where the
// ray caster can resolve the box (Embree intersects in float32, tests/README.md, "Numerical extremes").
#include "gather/final_gather.h"

#include "tests/extreme_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace radview {
namespace {

TEST(ExtremesGather, FiniteAtEveryScaleAndCoveredWhereFloatResolvesTheBox) {
  for (const test::Placement& placement : test::extremePlacements()) {
    const RadiosityMesh mesh = test::extremeBox(placement, true);
    for (Method interpolant : {Method::Gouraud, Method::CloughTocher}) {
      GatherSettings settings;
      settings.interpolant = interpolant;
      settings.width = 40;
      settings.height = 30;
      settings.camera = test::extremeCamera(placement, {0.3, 0.4, 0.35}, {0.9, 0.8, 0.95});
      FinalGather gather(mesh, settings);
      gather.addPasses(2);
      const LinearImage image = gather.image();
      size_t nonFinite = 0, uncovered = 0;
      for (size_t i = 0; i < image.rgba.size(); i += 4) {
        for (int c = 0; c < 4; ++c) nonFinite += !std::isfinite(image.rgba[i + c]);
        uncovered += image.rgba[i + 3] < 1.0f;
      }
      std::cout << placement.name << ", B^ " << int(interpolant) << ": " << nonFinite << " values not finite, "
                << uncovered << " pixels not fully covered\n";
      EXPECT_EQ(nonFinite, 0u) << placement.name;
      // float32 resolves 0.0078 at 1e5: a box 1e-3 across there is below Embree's resolution.
      if (placement.scale * 1e-3 > 1e-7 * glm::length(placement.origin)) {
        EXPECT_EQ(uncovered, 0u) << placement.name;
      }
    }
  }
}

}  // namespace
}  // namespace radview
