// The solver against an answer it did not compute: a receiver lit once by an emitter that
// reflects nothing and nothing occludes (tests/closed_form_scenes.h). With exact unoccluded
// form factors (C&W §4.9.2) and a visibility fraction of 1, every receiving node's value is
// Lambert's B(x) to rounding, through the same steps `radview solve` takes.
#include "solve/direct_light.h"
#include "solve/radiosity_solve.h"
#include "tests/closed_form_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace radview {
namespace {

constexpr double kTolerance = 1e-6;  // relative, per channel

// The largest |B - B_exact| / B_exact over the nodes of the receiver (polygon 0).
double largestRelativeError(const test::ClosedFormScene& s, const RadiosityMesh& mesh, Vec3* where) {
  std::vector<char> onReceiver(mesh.nodes.size(), 0);
  for (const Element& element : mesh.elements)
    if (element.surface == 0)
      for (uint32_t node : element.corners) onReceiver[node] = 1;
  double worst = 0.0;
  for (size_t i = 0; i < mesh.nodes.size(); ++i) {
    if (!onReceiver[i]) continue;
    const Rgb exact = s.B(mesh.nodes[i].position);
    for (int k = 0; k < 3; ++k) {
      const double error = std::abs(mesh.nodes[i].B[k] - exact[k]) / exact[k];
      if (error > worst) {
        worst = error;
        *where = mesh.nodes[i].position;
      }
    }
  }
  return worst;
}

// `radview solve`'s steps on the receiver meshed at 1/16 of its width, shot until no light is
// left unshot: the emitter's patches once each, then the receiver's, whose light reaches only
// the emitter (rho 0). The ambient term is then 0; subdivision values its new nodes by
// replaying the shots.
RadiosityMesh solved(const test::ClosedFormScene& s, bool subdivide) {
  SolveSettings settings;
  settings.patchSize = 1.0 / 16.0;
  settings.solver.stopUnshotFraction = 0.0;
  settings.subdivide = subdivide;
  SolveSummary summary;
  const RadiosityMesh mesh = solveRadiosity(s.scene, settings, summary);
  EXPECT_EQ(summary.progress.unshotFraction, 0.0);
  return mesh;
}

void expectExact(double tiltDegrees) {
  const test::ClosedFormScene s = test::emitterOverSquare(tiltDegrees);
  for (bool subdivide : {false, true}) {
    const RadiosityMesh mesh = solved(s, subdivide);
    Vec3 where(0.0);
    const double worst = largestRelativeError(s, mesh, &where);
    std::printf("tilt %g, %s: %zu nodes, largest relative error %.3g at (%g, %g, %g)\n", tiltDegrees,
                subdivide ? "subdivided" : "uniform", mesh.nodes.size(), worst, where.x, where.y, where.z);
    EXPECT_LE(worst, kTolerance) << "tilt " << tiltDegrees << (subdivide ? ", subdivided" : ", uniform");
  }
  // The direct light of a scene opened unsolved (meshAndLight) is exact too.
  Vec3 where(0.0);
  const double worst = largestRelativeError(s, meshAndLight(s.scene, 1.0 / 16.0), &where);
  std::printf("tilt %g, meshAndLight: largest relative error %.3g\n", tiltDegrees, worst);
  EXPECT_LE(worst, kTolerance) << "tilt " << tiltDegrees << ", meshAndLight";
}

TEST(ClosedFormSolveTest, NodalValuesAreExactUnderAParallelEmitter) { expectExact(0.0); }

TEST(ClosedFormSolveTest, NodalValuesAreExactUnderATiltedEmitter) { expectExact(30.0); }

}  // namespace
}  // namespace radview
