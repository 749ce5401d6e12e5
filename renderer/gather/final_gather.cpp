#include "gather/final_gather.h"

#include "core/error.h"
#include "core/limits.h"
#include "core/parallel_for.h"
#include "gather/hemisphere_sampling.h"
#include "gather/visible_elements.h"

#include <string>

namespace radview {

namespace {

constexpr double kPi = 3.14159265358979323846;
// A sample's coordinates of the GatherSequence (final_gather.h).
constexpr int kIndirectDimension = 0, kPixelDimension = 2, kEmitterDimension = 4;

GatherSettings checked(const GatherSettings& settings) {
  if (settings.width < 1 || settings.height < 1)
    throw Error("final gather: the image size " + std::to_string(settings.width) + "x" +
                std::to_string(settings.height) + " is empty");
  if (settings.emitterSamples < 1)
    throw Error("final gather: " + std::to_string(settings.emitterSamples) + " emitter samples: expected 1 or more");
  if (settings.runs < 1 || settings.runs > kMaxGatherRuns)
    throw Error("final gather: " + std::to_string(settings.runs) + " runs: expected 1 to " +
                std::to_string(kMaxGatherRuns));
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
    : mesh_(mesh),
      settings_(checked(settings)),
      interpolant_(makeInterpolant(mesh, settings.interpolant, settings.interpolantOptions)),
      caster_(std::make_unique<RayCaster>(elementScene(mesh))),
      emitters_(mesh),
      cameraRays_(settings.camera, settings.width, settings.height),
      sequence_(kEmitterDimension + 3 * settings_.emitterSamples),
      sum_(size_t(settings_.runs) * size_t(settings.width) * size_t(settings.height) * 4, 0.0),
      pass_(size_t(settings.width) * size_t(settings.height)) {
  normals_.reserve(mesh.elements.size());
  for (size_t e = 0; e < mesh.elements.size(); ++e) normals_.push_back(mesh.elementNormal(e));
}

// C&W eq. 9.9's integral over the emitters' own radiosity E: sampled by area on them.
Rgb FinalGather::directLight(const Vec3& x, const Vec3& n, const GatherSequence::PixelPoint& u, uint32_t& rays) const {
  if (emitters_.empty()) return Rgb(0.0);
  Rgb sum(0.0);
  for (int k = 0; k < settings_.emitterSamples; ++k) {
    const int first = kEmitterDimension + 3 * k;
    const EmitterSample s = emitters_.sample(u(first), u(first + 1), u(first + 2));
    const Vec3 d = s.position - x;
    const double r2 = glm::dot(d, d);
    if (!(r2 > 0.0)) continue;
    const Vec3 w = d / std::sqrt(r2);
    const double cosP = glm::dot(n, w), cosE = -glm::dot(s.normal, w);
    // Below x_p's horizon, or the emitter's back (it emits on its front only): G = 0.
    if (cosP <= 0.0 || cosE <= 0.0) continue;
    ++rays;
    if (caster_->occluded({x, n, s.position, s.normal})) continue;
    sum += s.E * (cosP * cosE / (kPi * r2 * s.pdfArea));
  }
  return sum / double(settings_.emitterSamples);
}

// The rest of eq. 9.9's integral, B^ - E over the surfaces, by one cosine-weighted direction:
// with pdf cos(theta) / pi, G dA' = cos(theta) / pi dw cancels to B^(x') - E(x').
Rgb FinalGather::indirectLight(const Vec3& x, const Vec3& n, const GatherSequence::PixelPoint& u,
                               uint32_t& rays) const {
  ++rays;
  const Vec3 direction = cosineWeightedDirection(n, u(kIndirectDimension), u(kIndirectDimension + 1));
  const std::optional<RayHit> hit = caster_->closestHit({x, direction, n});
  if (!hit || !hit->front) return Rgb(0.0);
  const uint32_t element = uint32_t(hit->polygon);
  const Material& material = mesh_.materials[size_t(mesh_.elements[element].material)];
  return interpolant_->evaluate(element, hit->position).B - material.E;
}

PixelSample FinalGather::samplePixel(int x, int y, int pass) const {
  return sample(x, y, pass, sequence_.point(uint32_t(pass / settings_.runs)));
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
  result.B = radiosityAt(element, seen->position, u, result.rays);
  return result;
}

// C&W eq. 9.9 at x, a point of `element` seen from its front.
Rgb FinalGather::radiosityAt(uint32_t element, const Vec3& x, const GatherSequence::PixelPoint& u,
                             uint32_t& rays) const {
  const Material& material = mesh_.materials[size_t(mesh_.elements[element].material)];
  const Vec3& n = normals_[element];
  return material.E + material.rho * (directLight(x, n, u, rays) + indirectLight(x, n, u, rays));
}

Rgb FinalGather::samplePoint(uint32_t element, const Vec3& x, uint64_t index, int pass) const {
  RADVIEW_CHECK(element < mesh_.elements.size());
  const uint32_t run = uint32_t(pass % settings_.runs), passOfRun = uint32_t(pass / settings_.runs);
  const std::vector<uint32_t> point = sequence_.point(passOfRun);
  // Keyed apart from the pixels' numbers, so that points and pixels are independent estimates.
  const GatherSequence::PixelPoint u(point, ~settings_.seed, index, passOfRun, run);
  uint32_t rays = 0;
  return radiosityAt(element, x, u, rays);
}

std::optional<RayHit> FinalGather::centreHit(int x, int y) const {
  const size_t pixel = size_t(y) * size_t(settings_.width) + size_t(x);
  if (!centreHits_.empty()) return centreHits_[pixel];
  return caster_->closestHit(cameraRays_.through(x + 0.5, y + 0.5));
}

int FinalGather::addPasses(int passes, const std::atomic<bool>* cancel) {
  auto cancelled = [&] { return cancel && cancel->load(std::memory_order_relaxed); };
  const int width = settings_.width;
  if (settings_.pixelCentres && centreHits_.empty() && passes > 0) {
    std::vector<std::optional<RayHit>> hits(pass_.size());
    parallelFor(
        size_t(settings_.height),
        [&](size_t y) {
          for (int x = 0; x < width; ++x)
            hits[y * size_t(width) + size_t(x)] = caster_->closestHit(cameraRays_.through(x + 0.5, y + 0.5));
        },
        1);
    centreHits_ = std::move(hits);
  }
  for (int p = 0; p < passes; ++p) {
    const std::vector<uint32_t> point = sequence_.point(uint32_t(passes_ / settings_.runs));
    double* sum = &sum_[size_t(passes_ % settings_.runs) * pass_.size() * 4];
    parallelFor(
        size_t(settings_.height),
        [&](size_t y) {
          if (cancelled()) return;
          for (int x = 0; x < width; ++x) pass_[y * size_t(width) + size_t(x)] = sample(x, int(y), passes_, point);
        },
        1);
    if (cancelled()) return p;
    // Added in pixel order after the pass, so the sums do not depend on the threads either.
    for (size_t i = 0; i < pass_.size(); ++i) {
      if (pass_[i].covered) {
        sum[4 * i + 0] += pass_[i].B.r;
        sum[4 * i + 1] += pass_[i].B.g;
        sum[4 * i + 2] += pass_[i].B.b;
        sum[4 * i + 3] += 1.0;
      }
      rays_ += pass_[i].rays;
    }
    ++passes_;
  }
  return passes;
}

int FinalGather::passesOfRun(int run) const {
  return passes_ / settings_.runs + (run < passes_ % settings_.runs ? 1 : 0);
}

namespace {

// The mean of `runs` runs' sums (final_gather.h's sum_) over `passes` passes in all.
LinearImage meanOfRuns(const double* sums, int runs, size_t pixels, int passes, int width, int height) {
  LinearImage image{width, height, std::vector<float>(pixels * 4, 0.0f)};
  if (passes == 0) return image;
  for (size_t i = 0; i < pixels; ++i) {
    double total[4] = {0.0, 0.0, 0.0, 0.0};
    for (int r = 0; r < runs; ++r)
      for (int c = 0; c < 4; ++c) total[c] += sums[(size_t(r) * pixels + i) * 4 + size_t(c)];
    if (total[3] == 0.0) continue;
    for (int c = 0; c < 3; ++c) image.rgba[4 * i + size_t(c)] = float(total[c] / total[3]);
    image.rgba[4 * i + 3] = float(total[3] / passes);
  }
  return image;
}

}  // namespace

LinearImage FinalGather::image() const {
  return meanOfRuns(sum_.data(), settings_.runs, pass_.size(), passes_, settings_.width, settings_.height);
}

LinearImage FinalGather::runImage(int run) const {
  RADVIEW_CHECK(run >= 0 && run < settings_.runs);
  return meanOfRuns(&sum_[size_t(run) * pass_.size() * 4], 1, pass_.size(), passesOfRun(run), settings_.width,
                    settings_.height);
}

}  // namespace radview
