#include "gather/final_gather.h"

#include "core/error.h"
#include "core/limits.h"
#include "core/parallel_for.h"
#include "gather/hemisphere_sampling.h"
#include "trace/visible_elements.h"

#include <string>

namespace radview {

namespace {

constexpr double kPi = 3.14159265358979323846;
// A sample's coordinates of the GatherSequence (final_gather.h).
constexpr int kIndirectDimension = 0, kPixelDimension = 2, kEmitterDimension = 4, kPerEmitterSample = 4;
// Indirect directions per pass at a fixed point, k: the indirect part carries most of the noise
// the controls leave, and a direction costs a quarter of a pass there, so each pass takes
// several; direction j of pass p is the sequence's point k p + j in coordinates 0-1, so that a
// run's directions are the sequence's first points, in its strata.
constexpr int kIndirectDirections = 4;
// The chance that an emitter sample at a fixed point casts its shadow ray (Russian roulette). The direct
// control already holds the hulls' shadows, so the residual is zero wherever they shadow as the
// surfaces do (in the Cornell box, everywhere): a quarter of the rays, the residual weighted by
// 4, keeps the estimate unbiased where it is not.
constexpr double kShadowRayChance = 0.25;

GatherSettings checked(const GatherSettings& settings) {
  if (settings.emitterSamples < 1)
    throw Error("final gather: " + std::to_string(settings.emitterSamples) + " emitter samples: expected 1 or more");
  return settings;
}

}  // namespace

bool operator==(const GatherSettings& a, const GatherSettings& b) {
  const InterpolantOptions &ia = a.interpolantOptions, &ib = b.interpolantOptions;
  const Camera &ca = a.camera, &cb = b.camera;
  return a.interpolant == b.interpolant && ia.diagonal == ib.diagonal && ia.cloughTocher == ib.cloughTocher &&
         ia.useStoredGradients == ib.useStoredGradients && a.seed == b.seed && a.width == b.width &&
         a.height == b.height && ca.eye == cb.eye && ca.target == cb.target && ca.up == cb.up && ca.yfov == cb.yfov &&
         ca.zNear == cb.zNear && ca.zFar == cb.zFar && a.emitterSamples == b.emitterSamples && a.runs == b.runs &&
         a.pixelCentres == b.pixelCentres;
}

FinalGather::FinalGather(const RadiosityMesh& mesh, const GatherSettings& settings)
    : ProgressiveImage("final gather", settings.width, settings.height, settings.runs),
      mesh_(mesh),
      settings_(checked(settings)),
      interpolant_(makeInterpolant(mesh, settings.interpolant, settings.interpolantOptions)),
      caster_(std::make_unique<RayCaster>(elementScene(mesh))),
      emitters_(mesh),
      control_(mesh),
      cameraRays_(settings.camera, settings.width, settings.height),
      sequence_(kEmitterDimension + kPerEmitterSample * settings_.emitterSamples) {
  normals_.reserve(mesh.elements.size());
  for (size_t e = 0; e < mesh.elements.size(); ++e) normals_.push_back(mesh.elementNormal(e));
}

// C&W eq. 9.9's integral over the emitters' own radiosity E, less its control (the same with
// nothing in the way): sampled by area on them, a sample counts only where something hides the
// emitter.
Rgb FinalGather::directResidual(const GatherPoint& point, const Vec3& n, const GatherSequence::PixelPoint& u,
                                uint32_t& rays) const {
  const Vec3& x = point.position;
  if (emitters_.empty()) return Rgb(0.0);
  Rgb sum(0.0);
  for (int k = 0; k < settings_.emitterSamples; ++k) {
    const int first = kEmitterDimension + kPerEmitterSample * k;
    const EmitterSample s = emitters_.sample(u(first), u(first + 1), u(first + 2));
    const Vec3 d = s.position - x;
    const double r2 = glm::dot(d, d);
    if (!(r2 > 0.0)) continue;
    const Vec3 w = d / std::sqrt(r2);
    const double cosP = glm::dot(n, w), cosE = -glm::dot(s.normal, w);
    // Below x_p's horizon, or the emitter's back (it emits on its front only): G = 0, in the
    // control as in the integrand (Lambert's formula clips at the horizon and is one-sided).
    const double chance = point.fixed ? kShadowRayChance : 1.0;
    if (cosP <= 0.0 || cosE <= 0.0 || u(first + 3) >= chance) continue;
    ++rays;
    const double seen = caster_->occluded({x, n, s.position, s.normal}) ? 0.0 : 1.0;
    const double controlSeen = point.fixed && control_.emitterSeen(x, s, point.facing) ? 1.0 : 0.0;
    if (seen != controlSeen) sum += s.E * ((seen - controlSeen) * cosP * cosE / (kPi * r2 * s.pdfArea * chance));
  }
  return sum / double(settings_.emitterSamples);
}

// The rest of eq. 9.9's integral, B^ - E over the surfaces, less its control, by cosine-
// weighted directions: with pdf cos(theta) / pi, G dA' = cos(theta) / pi dw cancels to
// B^(x') - E(x') at the surface met, and the control to the value of the hull met.
Rgb FinalGather::indirectResidual(const GatherPoint& point, const Vec3& n, const GatherSequence::PixelPoint& u,
                                  uint32_t& rays) const {
  const Vec3& x = point.position;
  const int directions = point.fixed ? kIndirectDirections : 1;
  Rgb sum(0.0);
  for (int j = 0; j < directions; ++j) {
    ++rays;
    // A plain point's one direction is the pass's own point, as its other coordinates are.
    const int word = point.fixed ? sequence_.dimensions() + 2 * j : kIndirectDimension;
    const Vec3 direction = cosineWeightedDirection(n, u(word, kIndirectDimension), u(word + 1, kIndirectDimension + 1));
    if (point.fixed) sum -= control_.along(x, direction, point.facing);
    const std::optional<RayHit> hit = caster_->closestHit({x, direction, n});
    if (!hit || !hit->front) continue;
    const uint32_t element = uint32_t(hit->polygon);
    const Material& material = mesh_.materials[size_t(mesh_.elements[element].material)];
    sum += interpolant_->evaluate(element, hit->position).B - material.E;
  }
  return sum / double(directions);
}

// The words a pass draws (GatherSequence::point(pass) in every coordinate), then coordinates
// 0-1 of points k pass .. k pass + k - 1 for its k indirect directions.
std::vector<uint32_t> FinalGather::passWords(uint32_t pass) const {
  std::vector<uint32_t> words = sequence_.point(pass);
  for (uint32_t j = 0; j < uint32_t(kIndirectDirections); ++j) {
    const std::vector<uint32_t> direction = sequence_.point(uint32_t(kIndirectDirections) * pass + j);
    words.push_back(direction[kIndirectDimension]);
    words.push_back(direction[kIndirectDimension + 1]);
  }
  return words;
}

PixelSample FinalGather::sample(int x, int y, int pass, const std::vector<uint32_t>& point) const {
  const uint64_t pixel = uint64_t(y) * uint64_t(settings_.width) + uint64_t(x);
  const uint32_t run = uint32_t(pass % settings_.runs), passOfRun = uint32_t(pass / settings_.runs);
  const GatherSequence::PixelPoint u(point, settings_.seed, pixel, passOfRun, run);
  PixelSample result;
  if (!settings_.pixelCentres || centreHits_.empty()) ++result.rays;  // the eye ray
  // At pixel centres every pass sees the same point: its hit is cast once (centreHits_).
  const std::optional<RayHit> seen =
      settings_.pixelCentres
          ? centreHit(x, y)
          : caster_->closestHit(cameraRays_.through(x + u(kPixelDimension), y + u(kPixelDimension + 1)));
  if (!seen) return result;
  result.covered = true;
  const uint32_t element = uint32_t(seen->polygon);
  if (!seen->front) {
    result.B = interpolant_->evaluate(element, seen->position).B;
    return result;
  }
  const GatherPoint at = !settings_.pixelCentres ? GatherPoint{element, seen->position}
                         : centrePoints_.empty() ? gatherPoint(element, seen->position)
                                                 : centrePoints_[pixel];
  result.B = radiosityAt(at, u, result.rays);
  return result;
}

GatherPoint FinalGather::gatherPoint(uint32_t element, const Vec3& x) const {
  RADVIEW_CHECK(element < mesh_.elements.size());
  const Vec3& n = normals_[element];
  const uint64_t facing = control_.facing(x);
  return {element, x, true, control_.integral(x, n, facing), facing};
}

// C&W eq. 9.9 at a point seen from its front: its controls' integrals plus one sample of what
// they leave out.
Rgb FinalGather::radiosityAt(const GatherPoint& point, const GatherSequence::PixelPoint& u, uint32_t& rays) const {
  const Material& material = mesh_.materials[size_t(mesh_.elements[point.element].material)];
  const Vec3& n = normals_[point.element];
  return material.E +
         material.rho * (point.controlled + directResidual(point, n, u, rays) + indirectResidual(point, n, u, rays));
}

Rgb FinalGather::samplePoint(const GatherPoint& point, uint64_t index, int pass) const {
  const uint32_t run = uint32_t(pass % settings_.runs), passOfRun = uint32_t(pass / settings_.runs);
  const std::vector<uint32_t> words = passWords(passOfRun);
  // Keyed apart from the pixels' numbers, so that points and pixels are independent estimates.
  const GatherSequence::PixelPoint u(words, ~settings_.seed, index, passOfRun, run);
  uint32_t rays = 0;
  return radiosityAt(point, u, rays);
}

std::optional<RayHit> FinalGather::centreHit(int x, int y) const {
  const size_t pixel = size_t(y) * size_t(settings_.width) + size_t(x);
  if (!centreHits_.empty()) return centreHits_[pixel];
  return caster_->closestHit(cameraRays_.through(x + 0.5, y + 0.5));
}

void FinalGather::prepare() {
  if (!settings_.pixelCentres) return;
  const int width = settings_.width;
  std::vector<std::optional<RayHit>> hits(size_t(width) * size_t(settings_.height));
  parallelFor(
      size_t(settings_.height),
      [&](size_t y) {
        for (int x = 0; x < width; ++x)
          hits[y * size_t(width) + size_t(x)] = caster_->closestHit(cameraRays_.through(x + 0.5, y + 0.5));
      },
      1);
  std::vector<GatherPoint> points(hits.size());
  parallelFor(
      hits.size(),
      [&](size_t i) {
        if (hits[i] && hits[i]->front) points[i] = gatherPoint(uint32_t(hits[i]->polygon), hits[i]->position);
      },
      256);
  centreHits_ = std::move(hits);
  centrePoints_ = std::move(points);
}

}  // namespace radview
