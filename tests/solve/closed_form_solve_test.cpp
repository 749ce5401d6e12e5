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

// `radview solve`'s steps on the receiver meshed at 1/16 of its width. Shot until no light is
// left unshot (`--unshot 0`): the emitter's patches once each, then the receiver's, whose light
// reaches only the emitter (rho 0); the ambient term is then 0. Subdivision values its new
// nodes by replaying the shots. Stopped at the default 1 % instead, the unshot light is on the
// receiver's patches, and the ambient term sends it only to the emitter, which reflects none.
struct Case {
  const char* name;
  bool subdivide;
  double stopUnshotFraction;
};
constexpr Case kCases[] = {
    {"uniform", false, 0.0}, {"subdivided", true, 0.0}, {"uniform, stopped at 1 %", false, 0.01}};

void expectExact(double tiltDegrees) {
  const test::ClosedFormScene s = test::emitterOverSquare(tiltDegrees);
  for (const Case& c : kCases) {
    SolveSettings settings;
    settings.patchSize = 1.0 / 16.0;
    settings.solver.stopUnshotFraction = c.stopUnshotFraction;
    settings.subdivide = c.subdivide;
    SolveSummary summary;
    const RadiosityMesh mesh = solveRadiosity(s.scene, settings, summary);
    Vec3 where(0.0);
    const double worst = largestRelativeError(s, mesh, &where);
    std::printf("tilt %g, %s: %zu nodes, %zu shots, largest relative error %.3g at (%g, %g, %g)\n", tiltDegrees, c.name,
                mesh.nodes.size(), summary.progress.shots, worst, where.x, where.y, where.z);
    EXPECT_LE(worst, kTolerance) << "tilt " << tiltDegrees << ", " << c.name;
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
