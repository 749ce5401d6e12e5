#include "gather/path_tracer.h"

#include "core/error.h"
#include "gather/hemisphere_sampling.h"
#include "trace/patch_sampler.h"

#include <algorithm>
#include <cmath>

namespace radview {

namespace {

constexpr double kPi = 3.14159265358979323846;
// A surface's coordinates of the sequence: its next direction (the sequence's best stratified
// pair for the first surface, whose indirect light varies most), the emitter sample, and the
// roulette.
constexpr int kDirection = 0, kEmitter = 2, kRoulette = 5, kPerSurface = 6;
// After all surfaces' coordinates: the point in the pixel.
constexpr int kPixel = kPerSurface * PathTracer::kSequenceBounces;
// The surfaces at which every path gathers light before roulette may end it. Ending paths early
// trades their cost for noise, and in a box of high reflectance (the Cornell box's white is
// about 0.75) much of B arrives along long paths.
constexpr int kSurfacesWithoutRoulette = 4;
// Roulette ends every path that carries anything within this many surfaces; only a scene of
// reflectance 1 throughout gets near it (and then B is infinite anyway).
constexpr int kMaxSurfaces = 1000;

double maxChannel(const Rgb& c) { return std::max({c.r, c.g, c.b}); }

// The power heuristic's weight of a sample drawn with density `chosen` where another strategy
// would have drawn it with density `other`, exponent 2 (Veach and Guibas 1995).
double powerWeight(double chosen, double other) {
  const double a = chosen * chosen, b = other * other;
  return a / (a + b);
}

}  // namespace

// A path's uniforms: coordinate d of the pass's point under the pixel's shift while the sequence
// has it, a counter-based stream beyond.
class PathTracer::PathNumbers {
 public:
  PathNumbers(const std::vector<uint32_t>& words, uint64_t seed, uint64_t key, uint32_t pass, uint32_t run)
      : point_(words, seed, key, pass, run), deeper_(SampleStream::forKey(seed, key, (uint64_t(run) << 32) | pass)) {}
  double operator()(int surface, int coordinate) const {
    const int d = kPerSurface * surface + coordinate;
    if (surface < kSequenceBounces) return point_(d);
    return double(deeper_.at(uint64_t(d - kPixel)) >> 11) * 0x1.0p-53;
  }
  double pixel(int axis) const { return point_(kPixel + axis); }

 private:
  GatherSequence::PixelPoint point_;
  SampleStream deeper_;
};

PathTracer::PathTracer(const Scene& surfaces, const PathTraceSettings& settings)
    : ProgressiveImage("path tracer", settings.width, settings.height, settings.runs),
      settings_(settings),
      materials_(surfaces.materials),
      caster_(std::make_unique<RayCaster>(surfaces)),
      emitters_(surfaces),
      cameraRays_(settings.camera, settings.width, settings.height),
      sequence_(kPixel + 2) {
  polygonMaterial_.reserve(surfaces.polygons.size());
  for (const Polygon& polygon : surfaces.polygons) polygonMaterial_.push_back(polygon.material);
}

std::vector<uint32_t> PathTracer::passWords(uint32_t pass) const { return sequence_.point(pass); }

Rgb PathTracer::radiosityAt(const Material& material, const Vec3& normal, const Vec3& x, const PathNumbers& u,
                            uint32_t& rays) const {
  Rgb B = material.E;
  Rgb beta = material.rho;
  Vec3 n = normal, p = x;
  for (int surface = 0; surface < kMaxSurfaces && maxChannel(beta) > 0.0; ++surface) {
    // Next-event estimation: a point on the emitters, seen or not.
    if (!emitters_.empty()) {
      const EmitterSample s =
          emitters_.sample(u(surface, kEmitter), u(surface, kEmitter + 1), u(surface, kEmitter + 2));
      const Vec3 d = s.position - p;
      const double r2 = glm::dot(d, d);
      const Vec3 w = r2 > 0.0 ? d / std::sqrt(r2) : Vec3(0.0);
      const double cosP = glm::dot(n, w), cosE = -glm::dot(s.normal, w);
      if (cosP > 0.0 && cosE > 0.0) {
        ++rays;
        if (!caster_->occluded({p, n, s.position, s.normal})) {
          const double pdfLight = s.pdfArea * r2 / cosE, pdfDirection = cosP / kPi;
          B += beta * s.E * (pdfDirection / pdfLight * powerWeight(pdfLight, pdfDirection));
        }
      }
    }
    // The path's next direction; an emitter it meets adds its E, weighed against next-event
    // estimation's chance of having drawn the same point.
    const Vec3 direction = cosineWeightedDirection(n, u(surface, kDirection), u(surface, kDirection + 1));
    ++rays;
    const std::optional<RayHit> hit = caster_->closestHit({p, direction, n});
    if (!hit || !hit->front) break;
    const Material& met = materialOf(hit->polygon);
    const Vec3& metNormal = caster_->normal(hit->polygon);
    if (met.isEmitter()) {
      const Vec3 d = hit->position - p;
      const double cosE = -glm::dot(metNormal, direction);
      const double pdfLight = emitters_.pdfArea(met.E) * glm::dot(d, d) / std::max(cosE, 1e-300);
      B += beta * met.E * powerWeight(glm::dot(n, direction) / kPi, pdfLight);
    }
    beta *= met.rho;
    if (surface + 1 >= kSurfacesWithoutRoulette) {
      // The square root lets paths live longer than their throughput alone would (as Cycles
      // does): a survivor's weight 1 / survive then stays small.
      const double survive = std::min(1.0, std::sqrt(maxChannel(beta)));
      if (u(surface, kRoulette) >= survive) break;
      beta /= survive;
    }
    n = metNormal;
    p = hit->position;
  }
  return B;
}

PixelSample PathTracer::sample(int x, int y, int pass, const std::vector<uint32_t>& words) const {
  const uint64_t pixel = uint64_t(y) * uint64_t(settings_.width) + uint64_t(x);
  const uint32_t run = uint32_t(pass % settings_.runs), passOfRun = uint32_t(pass / settings_.runs);
  const PathNumbers u(words, settings_.seed, pixel, passOfRun, run);
  PixelSample result;
  result.rays = 1;
  const Ray eye = settings_.pixelCentres ? cameraRays_.through(x + 0.5, y + 0.5)
                                         : cameraRays_.through(x + u.pixel(0), y + u.pixel(1));
  const std::optional<RayHit> seen = caster_->closestHit(eye);
  if (!seen) return result;
  result.covered = true;
  if (seen->front)
    result.B = radiosityAt(materialOf(seen->polygon), caster_->normal(seen->polygon), seen->position, u, result.rays);
  return result;
}

Rgb PathTracer::samplePoint(const Material& material, const Vec3& normal, const Vec3& x, uint64_t index,
                            int pass) const {
  const uint32_t run = uint32_t(pass % settings_.runs), passOfRun = uint32_t(pass / settings_.runs);
  const std::vector<uint32_t> words = passWords(passOfRun);
  // Keyed apart from the pixels' numbers, so that points and pixels are independent estimates.
  const PathNumbers u(words, ~settings_.seed, index, passOfRun, run);
  uint32_t rays = 0;
  return radiosityAt(material, normal, x, u, rays);
}

}  // namespace radview
