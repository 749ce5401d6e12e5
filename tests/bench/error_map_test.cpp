// Where a bench row loses: its signed difference from the reference (renderer/bench/error_map.h).
#include "bench/error_map.h"

#include "core/display_transform.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

LinearImage grey(std::vector<float> values) {
  LinearImage image{int(values.size()), 1, {}};
  for (float v : values) image.rgba.insert(image.rgba.end(), {v, v, v, 1.0f});
  return image;
}

TEST(ErrorMap, SignedDifferenceAtTheComparedPixelsOnly) {
  const LinearImage d = signedDifference(grey({0.5f, 0.3f, 0.9f}), grey({0.25f, 0.4f, 0.1f}), {0, 1});
  EXPECT_FLOAT_EQ(d.rgba[0], 0.25f);
  EXPECT_FLOAT_EQ(d.rgba[4], -0.1f);
  EXPECT_EQ(d.rgba[7], 1.0f);
  EXPECT_EQ(d.rgba[8], 0.0f) << "not compared";
  EXPECT_EQ(d.rgba[11], 0.0f);
}

TEST(ErrorMap, BrighterIsRedDarkerBlueAgreementWhite) {
  // Pixel 0 ten steps brighter (the end of a 10-step scale), 1 equal, 2 darker, 3 not compared.
  const double ten = srgbDecode(srgbEncode(0.2) + 10.0 / 255.0);
  const Image map =
      differenceMap(grey({float(ten), 0.2f, 0.1f, 0.7f}), grey({0.2f, 0.2f, 0.2f, 0.2f}), {0, 1, 2}, 1.0, 10.0);
  EXPECT_NEAR(map.rgba[0], 217, 1);  // red: 0.85
  EXPECT_NEAR(map.rgba[2], 26, 1);
  EXPECT_EQ(map.rgba[4], 255);  // white
  EXPECT_EQ(map.rgba[6], 255);
  EXPECT_GT(map.rgba[10], map.rgba[8]);  // blue
  EXPECT_EQ(map.rgba[12], 128);          // grey
}

}  // namespace
}  // namespace radview
