// The final gather's control variates (gather/control_variates.h) change its noise, not its
// answer: on the bundled Cornell box, where the blocks hide the lamp and the walls, the gather
// agrees at surface points with the plain estimator of eq. 9.9 (emitter sampling plus cosine-
// weighted directions, nothing in closed form) written out here, and its samples vary less.
#include "gather/final_gather.h"

#include "gather/emitter_sampler.h"
#include "gather/hemisphere_sampling.h"
#include "geom/polygon.h"
#include "import/load_file.h"
#include "trace/visible_elements.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace radview {
namespace {

struct Estimate {
  Rgb mean{0.0}, standardError{0.0};
  double variance = 0.0;  // of one sample, mean over the channels
};

template <typename Sample>
Estimate estimate(int samples, const Sample& sample) {
  Rgb sum(0.0), squares(0.0);
  for (int k = 0; k < samples; ++k) {
    const Rgb B = sample(k);
    sum += B;
    squares += B * B;
  }
  Estimate e;
  e.mean = sum / double(samples);
  const Rgb variance = squares / double(samples) - e.mean * e.mean;
  e.standardError = glm::sqrt(glm::max(variance, Rgb(0.0)) / double(samples));
  e.variance = (variance.r + variance.g + variance.b) / 3.0;
  return e;
}

TEST(GatherControlTest, AgreesWithThePlainEstimatorWhereTheBlocksHideTheLight) {
  const LoadedFile file = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box_solved.glb");
  const RadiosityMesh& mesh = file.mesh;
  GatherSettings settings;
  settings.width = settings.height = 1;
  const FinalGather gather(mesh, settings);

  const std::unique_ptr<Interpolant> interpolant = makeInterpolant(mesh, settings.interpolant);
  const RayCaster caster(elementScene(mesh));
  const EmitterSampler emitters(mesh);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  constexpr double kPi = 3.14159265358979323846;
  // eq. 9.9 at (element, x) by one emitter sample and one cosine-weighted direction.
  auto plainSample = [&](uint32_t element, const Vec3& x) {
    const Material& material = mesh.materials[size_t(mesh.elements[element].material)];
    const Vec3 n = mesh.elementNormal(element);
    Rgb direct(0.0), indirect(0.0);
    const EmitterSample s = emitters.sample(u(random), u(random), u(random));
    const Vec3 d = s.position - x;
    const double r2 = glm::dot(d, d), cosP = glm::dot(n, d) / std::sqrt(r2),
                 cosE = -glm::dot(s.normal, d) / std::sqrt(r2);
    if (cosP > 0.0 && cosE > 0.0 && !caster.occluded({x, n, s.position, s.normal}))
      direct = s.E * (cosP * cosE / (kPi * r2 * s.pdfArea));
    const std::optional<RayHit> hit = caster.closestHit({x, cosineWeightedDirection(n, u(random), u(random)), n});
    if (hit && hit->front)
      indirect = interpolant->evaluate(uint32_t(hit->polygon), hit->position).B -
                 mesh.materials[size_t(mesh.elements[hit->polygon].material)].E;
    return material.E + material.rho * (direct + indirect);
  };

  // Elements spread over the mesh: every surface of the box, shadowed and lit.
  constexpr int kPoints = 12, kSamples = 16384;
  double plainVariance = 0.0, gatherVariance = 0.0;
  int compared = 0;
  for (int k = 0; k < kPoints; ++k) {
    const uint32_t element = uint32_t((size_t(k) * 7919 + 13) % mesh.elements.size());
    if (mesh.materials[size_t(mesh.elements[element].material)].isEmitter()) continue;
    const Vec3 x = centroid(mesh.cornerPositions(element));
    const GatherPoint point = gather.gatherPoint(element, x);
    const Estimate controlled =
        estimate(kSamples, [&](int pass) { return gather.samplePoint(point, uint64_t(k), pass); });
    const Estimate plain = estimate(kSamples, [&](int) { return plainSample(element, x); });
    std::printf("element %5u: gather %.5f %.5f %.5f, plain %.5f %.5f %.5f (+- %.5f); sample variance %.2e vs %.2e\n",
                element, controlled.mean.r, controlled.mean.g, controlled.mean.b, plain.mean.r, plain.mean.g,
                plain.mean.b, plain.standardError.r, controlled.variance, plain.variance);
    for (int c = 0; c < 3; ++c) {
      const double tolerance = 5.0 * std::hypot(controlled.standardError[c], plain.standardError[c]) + 1e-9;
      EXPECT_LT(std::abs(controlled.mean[c] - plain.mean[c]), tolerance) << "element " << element << " channel " << c;
    }
    ++compared;
    // A point the surfaces enclose (the floor under a block) sees only their backs, which hide
    // as the hulls do not: there the control leaves the noise (control_variates.h).
    if (plain.variance == 0.0) continue;
    plainVariance += plain.variance;
    gatherVariance += controlled.variance;
  }
  ASSERT_GE(compared, kPoints - 2);
  std::printf("sample variance, all points: gather %.3e, plain %.3e (%.1fx less)\n", gatherVariance, plainVariance,
              plainVariance / gatherVariance);
  EXPECT_LT(gatherVariance, 0.25 * plainVariance);
}

}  // namespace
}  // namespace radview
