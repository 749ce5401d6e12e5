// displayDifference: the numbers the difference view reports, against hand-computed ones.
#include "core/image_difference.h"
#include "core/display_transform.h"
#include "core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace radview {
namespace {

LinearImage uniform(int width, int height, float value, float alpha = 1.0f) {
  LinearImage image{width, height, std::vector<float>(size_t(width) * height * 4, value)};
  for (size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = alpha;
  return image;
}

TEST(DisplayTransform, IsTheSrgbCurveAfterExposure) {
  EXPECT_DOUBLE_EQ(srgbEncode(0.0), 0.0);
  EXPECT_DOUBLE_EQ(srgbEncode(1.0), 1.0);
  EXPECT_DOUBLE_EQ(srgbEncode(0.002), 12.92 * 0.002);
  EXPECT_NEAR(srgbEncode(0.5), 0.7353569830524495, 1e-15);  // 1.055 * 0.5^(1/2.4) - 0.055
  EXPECT_DOUBLE_EQ(displayed(Rgb(0.25), 4.0).r, 1.0);       // exposure, then the clamp
  EXPECT_DOUBLE_EQ(luminance(Rgb(1.0)), 1.0);
}

TEST(DisplayDifference, OfAnImageWithItselfIsZero) {
  const LinearImage a = uniform(4, 3, 0.3f);
  const DisplayDifference d = displayDifference(a, ReferenceImage{a, true, "same"}, 1.0);
  EXPECT_EQ(d.pixels, 12u);
  EXPECT_EQ(d.rmse, 0.0);
  EXPECT_EQ(d.maxAbs, 0.0);
}

// A linear reference goes through the same exposure and tone map; a display one does not.
TEST(DisplayDifference, ComparesDisplayedLuminance) {
  const LinearImage render = uniform(2, 2, 0.5f);
  const double shown = srgbEncode(0.5 * 0.5);  // at exposure -1 stop
  const DisplayDifference linear = displayDifference(render, ReferenceImage{uniform(2, 2, 0.25f), true, "r"}, 0.5);
  EXPECT_NEAR(linear.meanSigned, shown - srgbEncode(0.125), 1e-7);
  EXPECT_NEAR(linear.rmse, std::abs(linear.meanSigned), 1e-12);
  const DisplayDifference display = displayDifference(render, ReferenceImage{uniform(2, 2, 0.25f), false, "r"}, 0.5);
  EXPECT_NEAR(display.meanSigned, shown - 0.25, 1e-7);
  EXPECT_NEAR(display.maxAbs, shown - 0.25, 1e-7);
}

// Only pixels covered, and finite, in both count.
TEST(DisplayDifference, SkipsUncoveredAndNonFinitePixels) {
  LinearImage render = uniform(3, 1, 0.5f);
  LinearImage reference = uniform(3, 1, 0.5f);
  render.rgba[3] = 0.0f;              // pixel 0 not covered in the render
  reference.rgba[4] = std::nanf("");  // pixel 1 NaN in the reference
  reference.rgba[8] = 0.0f;           // pixel 2 differs: black
  const DisplayDifference d = displayDifference(render, ReferenceImage{reference, true, "r"}, 1.0);
  EXPECT_EQ(d.pixels, 1u);
  EXPECT_NEAR(d.maxAbs, 0.2126 * srgbEncode(0.5), 1e-7);
}

TEST(DisplayDifference, RefusesImagesOfAnotherSizeNamingTheReference) {
  try {
    displayDifference(uniform(4, 4, 0.1f), ReferenceImage{uniform(4, 3, 0.1f), true, "ref.exr"}, 1.0);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("ref.exr: the reference is 4x3, the render 4x4"), std::string::npos)
        << e.what();
  }
}

// A float file is read back as linear, exactly; an 8-bit one as display colour.
TEST(ReferenceImage, FloatFilesAreLinearAndEightBitFilesDisplay) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  LinearImage image = uniform(3, 2, 0.0f);
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = (i % 4 == 3) ? 1.0f : float(i) * 0.37f;
  const std::string exr = (dir / "radview_reference_test.exr").string();
  writeLinearImage(image, exr);
  const ReferenceImage linear = readReferenceImage(exr);
  EXPECT_TRUE(linear.linear);
  EXPECT_EQ(linear.pixels.rgba, image.rgba);
  const std::string png = (dir / "radview_reference_test.png").string();
  writePng(Image{1, 1, {255, 0, 51, 255}}, png);
  const ReferenceImage display = readReferenceImage(png);
  EXPECT_FALSE(display.linear);
  EXPECT_FLOAT_EQ(display.pixels.rgba[0], 1.0f);
  EXPECT_FLOAT_EQ(display.pixels.rgba[2], 0.2f);
  EXPECT_THROW(readReferenceImage((dir / "radview_no_such_reference.exr").string()), Error);
}

}  // namespace
}  // namespace radview
