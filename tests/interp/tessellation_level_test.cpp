// The adaptive tessellation level keeps the display error of linear interpolation under the
// tolerance on a uniform split at the chosen level (the derivation's model; OpenGL's ring
// pattern, for which the level carries a factor of three more, is checked on the GPU in
// tests/gl/tessellation_test.cpp).
#include "interp/tessellation_level.h"
#include "interp/bezier_triangle.h"

#include <gtest/gtest.h>

#include <random>

namespace radview {
namespace {

double srgb(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

// Largest display error over sub-triangles of a level-L uniform split, sampled inside each.
template <size_t N>
double displayError(const std::array<Rgb, N>& net, int L, double s) {
  auto exact = [&](const Vec3& beta) { return evaluateBezier(net, beta).B; };
  double worst = 0.0;
  for (int i = 0; i < L; ++i)
    for (int j = 0; i + j < L; ++j)
      for (int upper = 0; upper < 2; ++upper) {
        if (upper && i + j + 1 >= L) continue;
        // Corners of the sub-triangle in barycentric coordinates.
        std::array<Vec3, 3> c;
        auto bary = [&](int a, int b) { return Vec3(double(a) / L, double(b) / L, double(L - a - b) / L); };
        if (!upper)
          c = {bary(i, j), bary(i + 1, j), bary(i, j + 1)};
        else
          c = {bary(i + 1, j), bary(i + 1, j + 1), bary(i, j + 1)};
        const std::array<Rgb, 3> f = {exact(c[0]), exact(c[1]), exact(c[2])};
        for (double u = 0.05; u < 1; u += 0.15)
          for (double v = 0.05; u + v < 1; v += 0.15) {
            const double w = 1 - u - v;
            const Rgb linear = u * f[0] + v * f[1] + w * f[2];
            const Rgb truth = exact(u * c[0] + v * c[1] + w * c[2]);
            for (int ch = 0; ch < 3; ++ch)
              worst = std::max(worst, std::abs(srgb(s * linear[ch]) - srgb(s * truth[ch])));
          }
      }
  return worst;
}

template <size_t N>
void checkRandomNets(int degree, double margin) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(0.0, 1.0), scale(-6.0, 2.0);
  const double tolerance = 0.5 / 255;
  int levelsAboveOne = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double amplitude = std::pow(10.0, scale(random));
    std::array<Rgb, N> net;
    for (Rgb& b : net) b = Rgb(value(random), value(random), value(random)) * amplitude;
    const double s = std::pow(2.0, scale(random));
    const TessellationLevels levels = adaptiveTessellationLevels(degree, net.data(), s, tolerance);
    if (levels.inner == kMaxTessellationLevel) continue;  // capped: no promise
    levelsAboveOne += levels.inner > 1;
    EXPECT_LE(displayError(net, levels.inner, s), margin * tolerance)
        << "trial " << trial << " amplitude " << amplitude << " exposure scale " << s << " level " << levels.inner;
  }
  EXPECT_GT(levelsAboveOne, 20);  // the nets do need tessellating
}

TEST(TessellationLevel, QuadraticPiecesMeetTheTolerance) { checkRandomNets<6>(2, 1.0); }

// For cubics the derivation holds to first order (the second derivative varies over a
// sub-triangle); on these nets it holds outright.
TEST(TessellationLevel, CubicPiecesMeetTheTolerance) { checkRandomNets<10>(3, 1.0); }

TEST(TessellationLevel, LinearAndSaturatedPiecesNeedNoTessellation) {
  const std::array<Rgb, 6> linear = linearBezierNet<6>({Rgb(0.1), Rgb(0.5), Rgb(0.9)});
  EXPECT_EQ(adaptiveTessellationLevels(2, linear.data(), 1.0, 0.5 / 255).inner, 1);
  std::array<Rgb, 6> bright;
  for (size_t i = 0; i < bright.size(); ++i) bright[i] = Rgb(2.0 + double(i * i));
  EXPECT_EQ(adaptiveTessellationLevels(2, bright.data(), 1.0, 0.5 / 255).inner, 1);  // all above white
}

TEST(TessellationLevel, SharedEdgesGetTheSameOuterLevelFromBothSides) {
  // Two quadratic pieces sharing the edge opposite corner 0 of the first and corner 1 of the
  // second, the edge's controls in opposite orders: both sides choose the same outer level.
  const std::array<Rgb, 6> a = {Rgb(0.3), Rgb(0.8), Rgb(0.1), Rgb(0.05), Rgb(0.6), Rgb(0.2)};
  // a's edge opposite corner 0 is b020 b011 b002 = a[3], a[4], a[5]; in b it is the edge
  // opposite corner 1: b200 b101 b002 = b[0], b[2], b[5], reversed.
  const std::array<Rgb, 6> b = {a[5], Rgb(0.9), a[4], Rgb(0.4), Rgb(0.7), a[3]};
  EXPECT_EQ(adaptiveTessellationLevels(2, a.data(), 4.0, 0.2 / 255).outer[0],
            adaptiveTessellationLevels(2, b.data(), 4.0, 0.2 / 255).outer[1]);
}

}  // namespace
}  // namespace radview
