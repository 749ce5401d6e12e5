// The element-to-node form factor against closed forms: Howell's catalogue for area-to-area
// factors (the point factor integrated over the receiver), with the visibility rays cast
// through Embree; and a half-hidden shooter, whose factor is the visible half's.
#include "solve/element_to_node.h"

#include "geom/polygon.h"
#include "trace/form_factor.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>

namespace radview {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kShooterSamples = 64;    // visibility samples per receiving point (an 8 x 8 grid)
constexpr int kReceiverPoints = 4096;  // receiver points in an area average (a 64 x 64 grid)

// (1 / A) * integral of f over the polygon, by a jittered grid of points (fixed seed).
double areaAverage(const std::vector<Vec3>& polygon, const std::function<double(const Vec3&)>& f) {
  const PatchSampler receiver(polygon, kReceiverPoints);
  SampleStream stream(12345);
  std::vector<AreaSample> points;
  receiver.draw(stream, points);
  double sum = 0.0;
  for (const AreaSample& p : points) sum += p.weight * f(p.position);
  return sum / receiver.area();
}

// F from the receiver polygon to the shooter: the estimator at every receiver point, rays
// cast through a scene of `occluders` (the receiver and shooter themselves included).
double sampledAreaToArea(const std::vector<Vec3>& receiver, const std::vector<Vec3>& shooter,
                         const std::vector<std::vector<Vec3>>& occluders, size_t& rays) {
  Scene scene;
  scene.materials = {{"grey", Rgb(0.5), Rgb(0.0)}};
  for (const auto& polygon : occluders) scene.polygons.push_back({polygon, 0});
  const RayCaster caster(scene);
  const PatchSampler sampler(shooter, kShooterSamples);
  const Vec3 n = unitNormal(receiver);
  std::vector<AreaSample> scratch;
  size_t point = 0;
  return areaAverage(receiver, [&](const Vec3& x) {
    SampleStream stream = SampleStream::forKey(7, 0, point++);
    return elementToNodeFormFactor({x, n}, sampler, stream, &caster, rays, scratch);
  });
}

double exactAreaToArea(const std::vector<Vec3>& receiver, const std::vector<Vec3>& shooter) {
  const Vec3 n = unitNormal(receiver);
  return areaAverage(receiver, [&](const Vec3& x) { return pointToPolygonFormFactor(x, n, shooter); });
}

// Howell's catalogue, C-11: directly opposed parallel rectangles a x b at distance c.
double parallelRectangles(double a, double b, double c) {
  const double X = a / c, Y = b / c;
  const double X2 = X * X, Y2 = Y * Y;
  return 2.0 / (kPi * X * Y) *
         (std::log(std::sqrt((1 + X2) * (1 + Y2) / (1 + X2 + Y2))) +
          X * std::sqrt(1 + Y2) * std::atan(X / std::sqrt(1 + Y2)) +
          Y * std::sqrt(1 + X2) * std::atan(Y / std::sqrt(1 + X2)) - X * std::atan(X) - Y * std::atan(Y));
}

// Howell's catalogue, C-41: coaxial parallel discs, from radius r1 to radius r2 at distance h.
double coaxialDiscs(double r1, double r2, double h) {
  const double R1 = r1 / h, R2 = r2 / h, X = 1 + (1 + R2 * R2) / (R1 * R1);
  return 0.5 * (X - std::sqrt(X * X - 4 * (R2 / R1) * (R2 / R1)));
}

// Howell's catalogue, C-14: from rectangle w x l to rectangle h x l sharing the edge l, at 90 deg.
double perpendicularRectangles(double w, double h, double l) {
  const double H = h / l, W = w / l, H2 = H * H, W2 = W * W, S = H2 + W2;
  const double logTerm = std::log((1 + W2) * (1 + H2) / (1 + S)) + W2 * std::log(W2 * (1 + S) / ((1 + W2) * S)) +
                         H2 * std::log(H2 * (1 + S) / ((1 + H2) * S));
  return (W * std::atan(1 / W) + H * std::atan(1 / H) - std::sqrt(S) * std::atan(1 / std::sqrt(S)) + 0.25 * logTerm) /
         (kPi * W);
}

std::vector<Vec3> rectangle(double x0, double x1, double y0, double y1, double z, bool facingDown) {
  std::vector<Vec3> r = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
  if (facingDown) std::reverse(r.begin(), r.end());
  return r;
}

std::vector<Vec3> disc(double radius, double z, int sides, bool facingDown) {
  std::vector<Vec3> d;
  for (int i = 0; i < sides; ++i)
    d.push_back({radius * std::cos(2 * kPi * i / sides), radius * std::sin(2 * kPi * i / sides), z});
  if (facingDown) std::reverse(d.begin(), d.end());
  return d;
}

TEST(ElementToNodeTest, HowellFormulasMatchTheExactPointFormFactorIntegrated) {
  // The catalogue transcriptions, checked against the exact point form factor integrated over
  // the receiver (4096 points): independent truths, agreeing to 1e-4.
  EXPECT_NEAR(parallelRectangles(1, 1, 1), 0.199825, 1e-6);
  EXPECT_NEAR(perpendicularRectangles(1, 1, 1), 0.200044, 1e-6);
  EXPECT_NEAR(exactAreaToArea(rectangle(0, 1, 0, 1, 0, false), rectangle(0, 1, 0, 1, 1, true)),
              parallelRectangles(1, 1, 1), 1e-4);
}

TEST(ElementToNodeTest, CoaxialParallelSquares) {
  // Unit squares 1 and 4 apart: Howell 0.19982 and 0.01861. The rays (64 per point, 4096
  // points) must all pass: within 0.1 %, the receiver quadrature's error.
  size_t rays = 0;
  for (double distance : {1.0, 4.0}) {
    const auto receiver = rectangle(0, 1, 0, 1, 0, false), shooter = rectangle(0, 1, 0, 1, distance, true);
    const double howell = parallelRectangles(1, 1, distance);
    EXPECT_NEAR(sampledAreaToArea(receiver, shooter, {receiver, shooter}, rays), howell, 0.001 * howell);
  }
  EXPECT_EQ(rays, 2u * kReceiverPoints * kShooterSamples);
}

TEST(ElementToNodeTest, CoaxialParallelDiscsAsPolygons) {
  // From a disc of radius 1 to one of radius 0.5, 0.5 above it, both as 64-gons. The
  // 64-gons' exact factor (the point form factor integrated) is the estimator's truth; it
  // differs from the round discs' closed form (Howell C-41, 0.19098) by 0.6 %: the 64-gons
  // miss 0.16 % of the discs' area, nearly all of it at the small disc's rim.
  const auto receiver = disc(1.0, 0.0, 64, false), shooter = disc(0.5, 0.5, 64, true);
  const double polygonExact = exactAreaToArea(receiver, shooter);
  EXPECT_NEAR(polygonExact, coaxialDiscs(1.0, 0.5, 0.5), 0.01 * polygonExact);
  size_t rays = 0;
  EXPECT_NEAR(sampledAreaToArea(receiver, shooter, {receiver, shooter}, rays), polygonExact, 1e-4 * polygonExact);
}

TEST(ElementToNodeTest, PerpendicularSquaresSharingAnEdge) {
  // Floor (receiver) and wall (shooter) unit squares sharing the edge y = 0: Howell 0.20004.
  // Points near the shared edge send rays that graze both squares: none may be stopped by
  // them (self-intersection), or the factor would come out low.
  const auto floor = rectangle(0, 1, 0, 1, 0, false);
  const std::vector<Vec3> wall = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};  // faces +y
  const double howell = perpendicularRectangles(1, 1, 1);
  size_t rays = 0;
  EXPECT_NEAR(sampledAreaToArea(floor, wall, {floor, wall}, rays), howell, 0.001 * howell);
}

TEST(ElementToNodeTest, HalfHiddenShooterGivesTheVisibleHalfsFactor) {
  // Unit squares 1 apart, and an occluder just below the shooter (1e-3) covering its half
  // x < 0.5: the factor is the half x > 0.5's, up to the occluder's 1e-3 parallax. 64 samples
  // per point (a grid whose cells the occluder's edge does not cut): within 0.5 %.
  const auto receiver = rectangle(0, 1, 0, 1, 0, false), shooter = rectangle(0, 1, 0, 1, 1, true);
  const auto occluder = rectangle(-2, 0.5, -2, 3, 0.999, true);
  size_t rays = 0;
  const double visibleHalf = exactAreaToArea(receiver, rectangle(0.5, 1, 0, 1, 1, true));
  EXPECT_NEAR(sampledAreaToArea(receiver, shooter, {receiver, shooter, occluder}, rays), visibleHalf,
              0.005 * visibleHalf);
}

TEST(ElementToNodeTest, PointsAcrossAShadowBoundary) {
  // Point by point across the half-hidden shooter's penumbra: each estimate within 0.02 of
  // the exact visible fraction's factor (absolute, at 64 samples).
  Scene scene;
  scene.materials = {{"grey", Rgb(0.5), Rgb(0.0)}};
  scene.polygons = {{rectangle(0, 1, 0, 1, 1, true), 0}, {rectangle(-2, 0.5, -2, 3, 0.999, true), 0}};
  const RayCaster caster(scene);
  const PatchSampler sampler(scene.polygons[0].vertices, kShooterSamples);
  std::vector<AreaSample> scratch;
  size_t rays = 0, key = 0;
  for (double x : {-0.5, 0.0, 0.25, 0.5, 0.75, 1.0, 1.5}) {
    const Vec3 p(x, 0.5, 0.0), n(0, 0, 1);
    SampleStream stream = SampleStream::forKey(3, 1, key++);
    const double sampled = elementToNodeFormFactor({p, n}, sampler, stream, &caster, rays, scratch);
    const double exact = pointToPolygonFormFactor(p, n, rectangle(0.5, 1, 0, 1, 1, true));
    EXPECT_NEAR(sampled, exact, 0.02) << "x " << x;
  }
}

TEST(ElementToNodeTest, SamplerWeightsSumToTheArea) {
  // Quads (bilinear, one piece) and concave polygons (triangles) alike.
  const std::vector<std::vector<Vec3>> polygons = {{{0, 0, 0}, {2, 0, 0}, {1.5, 1, 0}, {0.2, 1.3, 0}},
                                                   {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 0.5, 0}, {0, 2, 0}},
                                                   disc(1.0, 0.0, 7, false)};
  for (const auto& polygon : polygons) {
    const PatchSampler sampler(polygon, 16);
    SampleStream stream(1);
    std::vector<AreaSample> samples;
    sampler.draw(stream, samples);
    EXPECT_EQ(samples.size(), sampler.samples());
    double sum = 0.0;
    for (const AreaSample& s : samples) sum += s.weight;
    EXPECT_NEAR(sum, area(polygon), 0.02 * area(polygon));
  }
}

// A quad's sample weighs its cell's area times the bilinear map's Jacobian |dp/du x dp/dv| at
// the sample, which the sampler evaluates as a linear function of (u, v): checked against the
// cross product itself, at each sample's (u, v) found again by Newton's method, on a tilted
// trapezoid whose Jacobian varies by a factor of 3 across it.
TEST(ElementToNodeTest, QuadSampleWeightsAreTheBilinearJacobian) {
  const glm::dmat3 tilt = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(Vec3(1, 2, 3))));
  const Vec3 a = tilt * Vec3(0, 0, 0), b = tilt * Vec3(3, 0, 0), c = tilt * Vec3(2, 1, 0), d = tilt * Vec3(1, 1, 0);
  const PatchSampler sampler({a, b, c, d}, 16);
  ASSERT_EQ(sampler.samples(), 16u);
  const double cell = 1.0 / 4.0;
  SampleStream stream(3);
  std::vector<AreaSample> samples;
  sampler.draw(stream, samples);
  auto at = [&](double u, double v) { return (1 - v) * ((1 - u) * a + u * b) + v * ((1 - u) * d + u * c); };
  for (const AreaSample& sample : samples) {
    double u = 0.5, v = 0.5;
    Vec3 pu(0.0), pv(0.0);
    for (int iteration = 0; iteration < 20; ++iteration) {
      pu = (1 - v) * (b - a) + v * (c - d);
      pv = (1 - u) * (d - a) + u * (c - b);
      const Vec3 r = sample.position - at(u, v);
      // Least squares step: [pu pv]^T [pu pv] (du, dv) = [pu pv]^T r.
      const double A = glm::dot(pu, pu), B = glm::dot(pu, pv), C = glm::dot(pv, pv);
      const double det = A * C - B * B, ru = glm::dot(pu, r), rv = glm::dot(pv, r);
      u += (C * ru - B * rv) / det;
      v += (A * rv - B * ru) / det;
    }
    ASSERT_LT(glm::distance(at(u, v), sample.position), 1e-12);
    const double jacobian = glm::length(glm::cross(pu, pv));
    EXPECT_NEAR(sample.weight, jacobian * cell * cell, 1e-12) << "at (" << u << ", " << v << ")";
  }
}

}  // namespace
}  // namespace radview
