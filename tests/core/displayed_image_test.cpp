// The CPU's display of a linear image: the GL display pass's transform where a surface is
// seen, the background where none is, blended by coverage.
#include "core/displayed_image.h"

#include "core/display_transform.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

TEST(DisplayedImage, SurfaceBackgroundAndPartialCoverage) {
  // Three pixels: covered, empty, half covered; exposure one stop.
  const LinearImage linear{3, 1, {0.1f, 0.2f, 0.4f, 1.0f, 9.0f, 9.0f, 9.0f, 0.0f, 0.1f, 0.2f, 0.4f, 0.5f}};
  const Rgb background(0.08, 0.08, 0.09);
  const Image image = displayedImage(linear, 2.0, background);
  ASSERT_EQ(image.width, 3);
  ASSERT_EQ(image.rgba.size(), 12u);
  const Rgb shown = displayed(Rgb(0.1, 0.2, 0.4), 2.0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(image.rgba[size_t(c)], uint8_t(std::lround(255.0 * shown[c]))) << "covered, channel " << c;
    EXPECT_EQ(image.rgba[4 + size_t(c)], uint8_t(std::lround(255.0 * background[c])))
        << "empty: the background, whatever the colour channels hold";
    EXPECT_EQ(image.rgba[8 + size_t(c)], uint8_t(std::lround(255.0 * (0.5 * shown[c] + 0.5 * background[c]))))
        << "half covered, channel " << c;
  }
  for (int i = 0; i < 3; ++i) EXPECT_EQ(image.rgba[4 * size_t(i) + 3], 255);
  // sRGB(0.4 * 2 = 0.8) is 231 of 255.
  EXPECT_EQ(image.rgba[2], 231);
}

}  // namespace
}  // namespace radview
