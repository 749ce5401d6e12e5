// The difference view: what it subtracts (another method evaluated per pixel, or a reference
// image), that the two routes agree, its colours' signs, and its errors.
#include "core/camera.h"
#include "core/error.h"
#include "core/image_difference.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "import/load_file.h"
#include "tests/gl/oblique_view.h"

#include <gtest/gtest.h>

namespace radview::gl {
namespace {

constexpr int kSize = 96;

class DifferenceViewTest : public ::testing::Test {
 protected:
  DifferenceViewTest() {
    mesh = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/discontinuities.gltf").mesh;
    renderer.setMesh(mesh);
    camera = test::obliqueView();
  }
  LinearImage renderLinear(Method method, int tessellation = 0) {
    RenderSettings s;
    s.method = method;
    s.tessellation = tessellation;
    renderer.render(camera, s, kSize, kSize);
    return renderer.readLinear();
  }
  RenderSettings difference(Method method, Method against, int tessellation = 0) {
    RenderSettings s;
    s.method = method;
    s.tessellation = tessellation;
    s.view = DisplayView::Difference;
    s.comparisonMethod = against;
    return s;
  }

  EglContext context;
  MeshRenderer renderer;
  RadiosityMesh mesh;
  Camera camera;
};

// The comparison is the other method exactly per pixel, whatever the shown method's level.
TEST_F(DifferenceViewTest, ComparesWithTheOtherMethodPerPixel) {
  const LinearImage exact = renderLinear(Method::CloughTocher);
  renderer.render(camera, difference(Method::CloughTocher, Method::CloughTocher, 2), kSize, kSize);
  const ReferenceImage comparison = renderer.readComparison();
  EXPECT_TRUE(comparison.linear);
  EXPECT_EQ(comparison.pixels.rgba, exact.rgba);
  // ... and the level-2 tessellation differs from it, by less than a few 8-bit steps.
  const DisplayDifference d = displayDifference(renderer.readLinear(), comparison, 1.0);
  EXPECT_GT(d.pixels, 3000u);
  EXPECT_GT(d.maxAbs, 0.05 / 255.0);
  EXPECT_LT(d.maxAbs, 4.0 / 255.0);
}

// A method minus itself is zero everywhere: white on the scale, background off the surface.
TEST_F(DifferenceViewTest, AMethodMinusItselfIsWhite) {
  renderer.render(camera, difference(Method::C1Quadratic, Method::C1Quadratic), kSize, kSize);
  const DisplayDifference d = displayDifference(renderer.readLinear(), renderer.readComparison(), 1.0);
  EXPECT_EQ(d.maxAbs, 0.0);
  const Image display = renderer.readDisplay();
  const uint8_t* centre = &display.rgba[(size_t(kSize / 2) * kSize + kSize / 2) * 4];
  EXPECT_EQ(centre[0], 255);
  EXPECT_EQ(centre[1], 255);
  EXPECT_EQ(centre[2], 255);
}

// A float reference image is the same comparison as the method it was rendered with.
TEST_F(DifferenceViewTest, ALinearReferenceImageMatchesTheMethodItCameFrom) {
  renderer.setReferenceImage(ReferenceImage{renderLinear(Method::CloughTocher), true, "ct"});
  RenderSettings againstImage = difference(Method::Gouraud, Method::Gouraud);
  againstImage.comparison = RenderSettings::Comparison::Image;
  renderer.render(camera, againstImage, kSize, kSize);
  const DisplayDifference image = displayDifference(renderer.readLinear(), renderer.readComparison(), 1.0);
  renderer.render(camera, difference(Method::Gouraud, Method::CloughTocher), kSize, kSize);
  const DisplayDifference method = displayDifference(renderer.readLinear(), renderer.readComparison(), 1.0);
  EXPECT_GT(image.rmse, 0.0);
  EXPECT_EQ(image.pixels, method.pixels);
  EXPECT_DOUBLE_EQ(image.rmse, method.rmse);
  EXPECT_DOUBLE_EQ(image.maxAbs, method.maxAbs);
}

// Brighter than the comparison is red, darker blue.
TEST_F(DifferenceViewTest, BrighterIsRedDarkerIsBlue) {
  LinearImage reference = renderLinear(Method::Gouraud);
  for (size_t i = 0; i < reference.rgba.size(); ++i)
    if (i % 4 != 3) reference.rgba[i] *= 0.8f;
  renderer.setReferenceImage(ReferenceImage{reference, true, "darker"});
  RenderSettings s = difference(Method::Gouraud, Method::Gouraud);
  s.comparison = RenderSettings::Comparison::Image;
  renderer.render(camera, s, kSize, kSize);
  const Image brighter = renderer.readDisplay();
  const uint8_t* p = &brighter.rgba[(size_t(kSize / 2) * kSize + kSize / 2) * 4];
  EXPECT_GT(p[0], p[2] + 50);
  for (size_t i = 0; i < reference.rgba.size(); ++i)
    if (i % 4 != 3) reference.rgba[i] *= 1.5f * 1.5f;
  renderer.setReferenceImage(ReferenceImage{reference, true, "brighter"});
  renderer.render(camera, s, kSize, kSize);
  const Image darker = renderer.readDisplay();
  const uint8_t* q = &darker.rgba[(size_t(kSize / 2) * kSize + kSize / 2) * 4];
  EXPECT_GT(q[2], q[0] + 50);
}

TEST_F(DifferenceViewTest, WithoutAReferenceImageIsAnError) {
  RenderSettings s = difference(Method::Gouraud, Method::Gouraud);
  s.comparison = RenderSettings::Comparison::Image;
  EXPECT_THROW(renderer.render(camera, s, kSize, kSize), Error);
}

}  // namespace
}  // namespace radview::gl
