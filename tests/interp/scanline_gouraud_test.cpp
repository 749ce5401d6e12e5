// Scanline Gouraud (C&W fig. 9.7) against what the text says it does.
#include "interp/scanline_gouraud.h"

#include "core/camera.h"
#include "core/error.h"
#include "interp/interpolant.h"

#include <gtest/gtest.h>
#include <glm/gtx/rotate_vector.hpp>

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
                    (triangle[2].x - triangle[1].x) * (p.y - triangle[2].y)) /
                   d;
  const double v = ((triangle[2].y - triangle[0].y) * (p.x - triangle[2].x) +
                    (triangle[0].x - triangle[2].x) * (p.y - triangle[2].y)) /
                   d;
  const Rgb want(u, v, 1 - u - v);
  for (double angle = 0; angle < 360; angle += 17) {
    const auto value = scanlineGouraud(rotated(triangle, angle), values, glm::rotate(p, glm::radians(angle)));
    ASSERT_TRUE(value.has_value()) << angle;
    EXPECT_NEAR(glm::length(value->B - want), 0.0, 1e-12) << angle;
  }
}

TEST(ScanlineGouraud, GradientIsTheDerivativeWithinTheSpan) {
  // An irregular quad with every value different: central differences at points inside a
  // span (away from its ends and from the corners' scanlines) match the analytic derivatives.
  const std::vector<Vec2> quad = {{-1, -1.2}, {1.3, -0.8}, {0.9, 1.1}, {-1.1, 0.7}};
  const std::vector<Rgb> values = {Rgb(0.9, 0.2, 5), Rgb(0.1, 0.4, 1), Rgb(0.7, 0.8, -2), Rgb(0.3, 0.1, 3)};
  const double h = 1e-6;
  for (const Vec2& p : {Vec2(0.1, 0.2), Vec2(-0.5, -0.3), Vec2(0.6, 0.5), Vec2(0.0, -0.9)}) {
    const auto at = scanlineGouraud(quad, values, p);
    const auto px = scanlineGouraud(quad, values, p + Vec2(h, 0)), mx = scanlineGouraud(quad, values, p - Vec2(h, 0));
    const auto py = scanlineGouraud(quad, values, p + Vec2(0, h)), my = scanlineGouraud(quad, values, p - Vec2(0, h));
    ASSERT_TRUE(at && px && mx && py && my);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(at->gradient[c].x, (px->B[c] - mx->B[c]) / (2 * h), 1e-6) << "d/dx, channel " << c;
      EXPECT_NEAR(at->gradient[c].y, (py->B[c] - my->B[c]) / (2 * h), 1e-6) << "d/dy, channel " << c;
    }
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
  EXPECT_NEAR(upright->B.r, 0.5, 1e-12);  // axis-aligned: the mean of the four
  // Rotated 45 degrees clockwise, the scanline through the centre joins corners 0 and 2
  // (values 0.9 and 0.7): the centre shows their mean.
  EXPECT_NEAR(diamond->B.r, 0.8, 1e-12);
  // The same polygon rotated by 90 degrees more: corners 1 and 3 span it.
  const auto otherDiamond = scanlineGouraud(rotated(quad, 45.0), values, {0.0, 0.0});
  ASSERT_TRUE(otherDiamond);
  EXPECT_NEAR(otherDiamond->B.r, 0.2, 1e-12);
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
  EXPECT_GT(std::abs(below->B.r - above->B.r), 0.05);
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
  EXPECT_NEAR(justAbove->B.r, 0.0, 1e-6);
  EXPECT_NEAR(justBelow->B.r, 1.0, 1e-6);
  // Turn the view 30 degrees: the T-vertex's edges now span scanlines and its value shows.
  const auto turned =
      scanlineGouraud(rotated(above, 30.0), aboveValues, glm::rotate(Vec2(1.0, 0.05), glm::radians(30.0)));
  ASSERT_TRUE(turned);
  EXPECT_GT(turned->B.r, 0.5);
}

// The interpolant of the surface: a quad seen obliquely. Its value is the screen's scanline
// value at the point's projection, so turning the view changes it (fig. 9.8), and its surface
// gradient is the derivative along the surface (central differences in the quad's plane).
TEST(ScanlineGouraud, AsAnInterpolantItDependsOnTheViewAndItsGradientIsAlongTheSurface) {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"m", Rgb(0.5), Rgb(0.0)});
  const Vec3 corners[] = {{-0.5, -0.5, 0}, {0.5, -0.45, 0}, {0.6, 0.5, 0}, {-0.45, 0.4, 0}};
  const double values[] = {0.9, 0.1, 0.7, 0.3};
  for (int i = 0; i < 4; ++i) mesh.nodes.push_back({corners[i], Rgb(values[i], 1 - values[i], 2 * values[i]), {}});
  mesh.elements.push_back(Element{{0, 1, 2, 3}, {}, 0, 0});
  Camera camera;
  camera.eye = {0.3, -1.1, 0.9};
  camera.up = {0.2, 0, 1};
  InterpolantOptions options;
  options.view = ScreenView{camera.clipFromWorld(4.0 / 3.0), Vec2(640, 480)};
  const auto oblique = makeInterpolant(mesh, Method::ScanlineGouraud, options);
  roll(camera, glm::radians(45.0));
  options.view = ScreenView{camera.clipFromWorld(4.0 / 3.0), Vec2(640, 480)};
  const auto rolled = makeInterpolant(mesh, Method::ScanlineGouraud, options);
  const double h = 1e-6;
  for (const Vec3& x : {Vec3(0.05, 0.02, 0), Vec3(-0.2, 0.2, 0), Vec3(0.3, -0.25, 0)}) {
    const Sample s = oblique->evaluate(0, x);
    EXPECT_GT(std::abs(rolled->evaluate(0, x).B.r - s.B.r), 1e-3) << "the same point, another view";
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.gradient[c].z, 0.0, 1e-12) << "in the plane";
    for (const Vec3& t : {Vec3(1, 0, 0), Vec3(0, 1, 0)}) {
      const double along = (oblique->evaluate(0, x + h * t).B.g - oblique->evaluate(0, x - h * t).B.g) / (2 * h);
      EXPECT_NEAR(glm::dot(s.gradient[1], t), along, 1e-5) << "at " << x.x << " " << x.y;
    }
  }
  EXPECT_THROW(makeInterpolant(mesh, Method::ScanlineGouraud), Error) << "without a view";
}

}  // namespace
}  // namespace radview
