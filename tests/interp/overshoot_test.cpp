// Overshoot at a step in value (the requirement 6; C&W §9.2.2, fig. 9.14): a unit
// step B = 0 for x < 1/2, 1 for x >= 1/2, on an 8 x 8 jittered mesh whose column x = 1/2 is
// straight, so the step runs along element edges. Overshoot = max B - 1, undershoot = -min B,
// over 100 .. 200 random points of every element.
//  - Tagged C-1 (the line's nodes duplicated, each side keeping its own value): every method
//    builds each side from that side's constant data alone, so nothing overshoots: pinned to
//    round-off (B <= 1 + 4 eps, B >= 0 exactly).
//  - Untagged (one node per position on the line, valued 1/2 or 1): the C1 methods smooth
//    over the step and overshoot on both sides, as the book says of C1 quadratic (fig. 9.14b);
//    so does quadratic Lagrange on quadratic elements; linear and bilinear cannot (their
//    values are convex combinations of the nodal values). Recorded, and asserted > 1% for the
//    C1 methods so that a broken C-1 handling, or a change to the untagged case, is noticed.
#include "interp/interpolant.h"
#include "tests/interp/test_meshes.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

using namespace test;

const Plane plane;
constexpr double eps = std::numeric_limits<double>::epsilon();

struct Extremes {
  double over = -1e300, under = -1e300;  // max B - 1, -min B, over all channels
};

Extremes extremes(const RadiosityMesh& mesh, const MethodCase& m, int pointsPerElement = 200) {
  const auto interpolant = makeInterpolant(mesh, m.method, m.options);
  std::mt19937 random(3);
  Extremes out;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (int k = 0; k < pointsPerElement; ++k) {
      const Rgb B = interpolant->evaluate(e, randomPointIn(mesh, e, random)).B;
      for (int c = 0; c < 3; ++c) {
        out.over = std::max(out.over, B[c] - 1.0);
        out.under = std::max(out.under, -B[c]);
      }
    }
  return out;
}

enum class Line { Half, One, CutCm1 };
const char* name(Line line) {
  return line == Line::Half  ? "untagged, 1/2 on the line"
         : line == Line::One ? "untagged, 1 on the line"
                             : "tagged C-1";
}

// The step mesh: triangles, quads or quadratic triangles.
RadiosityMesh stepMesh(int kind, Line line, uint32_t seed) {
  const Field zero = [](const Vec2&) { return Rgb(0.0); };
  RadiosityMesh mesh = gridMesh(8, kind == 1, kind == 1 ? 0.2 : 0.3, zero, seed, plane);
  straightenGridLines(mesh, 8, 4, -1, plane);
  if (kind == 2) mesh = withMidEdgeNodes(mesh, zero, plane);
  for (Node& n : mesh.nodes) {
    const double x = plane.coords(n.position).x;
    n.B = Rgb(std::abs(x - 0.5) < 1e-9 ? (line == Line::Half ? 0.5 : 1.0) : x < 0.5 ? 0.0 : 1.0);
  }
  if (line == Line::CutCm1)
    for (const auto& [left, right] : cutAlongLine(mesh, 0.5, plane)) {
      mesh.nodes[left].B = Rgb(0.0);
      mesh.nodes[right].B = Rgb(1.0);
    }
  // A step has no gradient to store: zero everywhere off the line, undefined on it. Stored
  // zero gradients are tested too (then the C1 patches are flat at every node).
  return mesh;
}
const char* kindName(int kind) { return kind == 0 ? "triangles" : kind == 1 ? "quads" : "quadratic triangles"; }

bool isC1(const MethodCase& m) { return m.method == Method::C1Quadratic || m.method == Method::CloughTocher; }

TEST(Overshoot, NoMethodOvershootsAStepTaggedCMinus1) {
  for (uint32_t seed = 1; seed <= 2; ++seed)
    for (int kind = 0; kind < 3; ++kind)
      for (bool stored : {false, true}) {
        RadiosityMesh mesh = stepMesh(kind, Line::CutCm1, seed);
        mesh.hasGradients = stored;
        for (const MethodCase& m : allMethods(true)) {
          const Extremes x = extremes(mesh, m, 100);
          EXPECT_LE(x.over, 4 * eps) << "seed " << seed << ", " << kindName(kind) << ", " << m.name;
          EXPECT_LE(x.under, 0.0) << "seed " << seed << ", " << kindName(kind) << ", " << m.name;
        }
      }
}

TEST(Overshoot, UntaggedTheC1MethodsOvershootAndLinearDoesNot) {
  for (int kind = 0; kind < 3; ++kind)
    for (Line line : {Line::Half, Line::One}) {
      const RadiosityMesh mesh = stepMesh(kind, line, 1);
      for (const MethodCase& m : allMethods(false)) {
        if (kind == 1 && m.method == Method::Quadratic) continue;  // quads without mid-edge nodes
        const Extremes x = extremes(mesh, m);
        std::printf("[ figures  ] step, %-19s %-26s %-24s overshoot %8.4f  undershoot %8.4f\n", kindName(kind),
                    name(line), m.name.c_str(), x.over, x.under);
        const std::string input = std::string(kindName(kind)) + ", " + name(line) + ", " + m.name;
        if (isC1(m)) {
          EXPECT_GT(std::max(x.over, x.under), 0.01) << input << ": no overshoot over an untagged step?";
        } else if (m.method != Method::Quadratic || kind != 2) {
          EXPECT_LE(x.over, 4 * eps) << input;  // convex combinations of the nodal values
          EXPECT_LE(x.under, 0.0) << input;
        }
      }
    }
}

TEST(Overshoot, StoredZeroGradientsKeepTheC1MethodsInRange) {
  // With flat tangent planes at every node the Bezier control values are convex combinations
  // of the nodal values (Clough-Tocher's inner c are the mean of the edge's b, everything
  // else averages), so the patches stay within [0, 1]: overshoot comes from the estimated
  // gradients, which see the step as a slope.
  for (Line line : {Line::Half, Line::One}) {
    RadiosityMesh mesh = stepMesh(0, line, 1);
    mesh.hasGradients = true;
    for (const MethodCase& m : c1Methods(true)) {
      const Extremes x = extremes(mesh, m);
      EXPECT_LE(x.over, 4 * eps) << name(line) << ", " << m.name;
      EXPECT_LE(x.under, 4 * eps) << name(line) << ", " << m.name;
    }
  }
}

}  // namespace
}  // namespace radview
