// Scanline Gouraud (C&W fig. 9.7) against what the text says it does.
#include "interp/scanline_gouraud.h"

#include <glm/gtx/rotate_vector.hpp>
#include <gtest/gtest.h>

namespace radview {
namespace {

std::vector<Vec2> rotated(const std::vector<Vec2>& polygon, double degrees) {
  std::vector<Vec2> out;
  for (const Vec2& p : polygon) out.push_back(glm::rotate(p, glm::radians(degrees)));
  return out;
}

TEST(ScanlineGouraud, TrianglesAreOrientationInvariant) {
  const std::vector<Vec2> triangle = {{0, 0}, {3, 0.5}, {1, 2}};
  const std::vector<Rgb> values = {Rgb(1, 0, 0), Rgb(0, 1, 0), Rgb(0, 0, 1)};
  const Vec2 p(1.3, 0.9);  // inside
  // Barycentric value at p.
  const double d = (triangle[1].y - triangle[2].y) * (triangle[0].x - triangle[2].x) +
                   (triangle[2].x - triangle[1].x) * (triangle[0].y - triangle[2].y);
  const double u = ((triangle[1].y - triangle[2].y) * (p.x - triangle[2].x) +
                    (triangle[2].x - triangle[1].x) * (p.y - triangle[2].y)) / d;
  const double v = ((triangle[2].y - triangle[0].y) * (p.x - triangle[2].x) +
                    (triangle[0].x - triangle[2].x) * (p.y - triangle[2].y)) / d;
  const Rgb want(u, v, 1 - u - v);
  for (double angle = 0; angle < 360; angle += 17) {
    const auto value = scanlineGouraud(rotated(triangle, angle), values, glm::rotate(p, glm::radians(angle)));
    ASSERT_TRUE(value.has_value()) << angle;
    EXPECT_NEAR(glm::length(*value - want), 0.0, 1e-12) << angle;
  }
}

TEST(ScanlineGouraud, TheFig98QuadChangesWithItsOrientation) {
  // One quad, values 0.9 0.1 0.7 0.3, rotated 45 degrees at a time: the centre's value
  // depends on which edges span its scanline.
  const std::vector<Vec2> quad = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const std::vector<Rgb> values = {Rgb(0.9), Rgb(0.1), Rgb(0.7), Rgb(0.3)};
  const auto upright = scanlineGouraud(quad, values, {0.0, 0.0});
  const auto diamond = scanlineGouraud(rotated(quad, -45.0), values, {0.0, 0.0});
  ASSERT_TRUE(upright && diamond);
  EXPECT_NEAR(upright->r, 0.5, 1e-12);   // axis-aligned: the mean of the four
  // Rotated 45 degrees clockwise, the scanline through the centre joins corners 0 and 2
  // (values 0.9 and 0.7): the centre shows their mean.
  EXPECT_NEAR(diamond->r, 0.8, 1e-12);
  // The same polygon rotated by 90 degrees more: corners 1 and 3 span it.
  const auto otherDiamond = scanlineGouraud(rotated(quad, 45.0), values, {0.0, 0.0});
  ASSERT_TRUE(otherDiamond);
  EXPECT_NEAR(otherDiamond->r, 0.2, 1e-12);
}

TEST(ScanlineGouraud, ConcavePolygonJumpsBetweenScanlines) {
  // A U shape: below the notch one span covers the whole width, above it two spans do. A
  // point in the left arm, just above and just below the notch's floor, gets values
  // interpolated between different edges: a discontinuity inside the polygon.
  const std::vector<Vec2> u = {{0, 0}, {4, 0}, {4, 3}, {3, 3}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  const std::vector<Rgb> values = {Rgb(0), Rgb(1), Rgb(1), Rgb(0.2), Rgb(0.5), Rgb(0.9), Rgb(0.1), Rgb(0)};
  const auto below = scanlineGouraud(u, values, {0.5, 1.0 - 1e-9});
  const auto above = scanlineGouraud(u, values, {0.5, 1.0 + 1e-9});
  ASSERT_TRUE(below && above);
  EXPECT_GT(std::abs(below->r - above->r), 0.05);
  EXPECT_FALSE(scanlineGouraud(u, values, {2.0, 2.0}).has_value());  // in the notch
}

TEST(ScanlineGouraud, TVertexOnAScanlineIsIgnoredAndTheShadingJumps) {
  // Above: one element whose bottom edge carries the T-vertex (1, 0) of the two finer
  // elements below it, valued 1 where everything else is 0. With that edge along a scanline
  // (C&W §9.2), the scanline just above it interpolates between the element's outer edges
  // and never sees the T-vertex; the one just below does.
  const std::vector<Vec2> above = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}};
  const std::vector<Rgb> aboveValues = {Rgb(0), Rgb(1), Rgb(0), Rgb(0), Rgb(0)};
  const std::vector<Vec2> belowLeft = {{0, -1}, {1, -1}, {1, 0}, {0, 0}};
  const std::vector<Rgb> belowLeftValues = {Rgb(0), Rgb(0), Rgb(1), Rgb(0)};
  const auto justAbove = scanlineGouraud(above, aboveValues, {1.0 - 1e-9, 1e-9});
  const auto justBelow = scanlineGouraud(belowLeft, belowLeftValues, {1.0 - 1e-9, -1e-9});
  ASSERT_TRUE(justAbove && justBelow);
  EXPECT_NEAR(justAbove->r, 0.0, 1e-6);
  EXPECT_NEAR(justBelow->r, 1.0, 1e-6);
  // Turn the view 30 degrees: the T-vertex's edges now span scanlines and its value shows.
  const auto turned =
      scanlineGouraud(rotated(above, 30.0), aboveValues, glm::rotate(Vec2(1.0, 0.05), glm::radians(30.0)));
  ASSERT_TRUE(turned);
  EXPECT_GT(turned->r, 0.5);
}

}  // namespace
}  // namespace radview
