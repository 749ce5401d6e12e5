#pragma once
// The true image of radview's scene model, without a radiosity solution: Monte Carlo paths
// through the mesh's surfaces estimate the radiosity equation itself (C&W eq. 2.54 in its
// continuous form),
//   B(x) = E(x) + rho(x) * integral over the surfaces of B(x') G(x, x') V(x, x') dA',
// by expanding B under the integral recursively instead of taking it from a solution (the final
// gather, final_gather.h, stops after one step and reads B^ there). It is radview's ground truth:
// what a converged solution and a perfect interpolant would both show.
//
// The estimator, per pixel and pass (one path per pixel per pass), in units of B (exitance: a
// Lambertian surface's radiance times pi, so a cosine-weighted direction carries weight rho):
//  - the eye ray through a jittered point of the pixel, or through its centre (pixelCentres: the
//    bench's reference, sampled where the GL renderer evaluates a method); B = E there plus the
//    reflected part below;
//  - at each surface point x of the path, with throughput beta (the product of the reflectances
//    so far, rho(x) included), two estimates of the light arriving from the emitters, combined
//    by multiple importance sampling with the power heuristic (Veach and Guibas 1995):
//      next-event estimation: a point on the emitters by power (EmitterSampler) and its shadow
//      ray: beta E cos(theta_x) cos(theta_e) / (pi r^2 pdf_A) w_light;
//      the path's own next direction, cosine-weighted: where it meets an emitter's front,
//      beta E w_direction;
//    and the path goes on from the point that direction meets;
//  - Russian roulette after the fourth surface: the path survives with probability
//    min(1, sqrt(max channel of beta)) and beta is divided by it, so the estimate stays unbiased
//    and long paths cost in proportion to what they carry.
//
// Decisions where the book is silent, as the solver and the gather take them:
//  - Surfaces are one-sided: a polygon's back reflects and emits nothing, and a path that meets
//    it ends there (a back face is black). An eye ray that sees one shows B = 0.
//  - Emitters emit on their front only, and reflect like any surface.
//
// Numbers: the path's first kSequenceBounces surfaces draw from pass `pass`'s point of a
// GatherSequence, shifted by the pixel's own words (as the gather's: stratified across passes,
// independent between pixels and runs); deeper surfaces, which carry little, draw from a
// counter-based stream keyed by the seed, the pixel and the pass. Every pixel's path depends on
// nothing else, so the image is the same for any thread count.
#include "core/camera.h"
#include "gather/emitter_sampler.h"
#include "gather/gather_sequence.h"
#include "gather/progressive_image.h"
#include "scene/scene.h"
#include "trace/camera_rays.h"
#include "trace/ray_caster.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace radview {

struct PathTraceSettings {
  uint64_t seed = 1;
  int width = 256, height = 256;
  Camera camera;
  // Independent runs of the estimator (ProgressiveImage): their spread is the image's noise.
  int runs = 1;
  // Every eye ray through the pixel's centre (as the GL renderer samples it) instead of a point
  // jittered over the pixel.
  bool pixelCentres = false;
};

class PathTracer : public ProgressiveImage {
 public:
  // The surfaces: a scene's polygons as the file gives them (fewest polygons, fastest rays), or
  // a solution's elements (elementScene); only their geometry and materials are used, so a scene
  // and a solution of it have the same truth. Throws Error for a size below 1x1 or runs out of
  // range.
  PathTracer(const Scene& surfaces, const PathTraceSettings& settings);

  const PathTraceSettings& settings() const { return settings_; }

  // One path's estimate of B at a surface point x of `material` whose front faces along the unit
  // `normal` (a node, a sample point): path number `index`'s sample `pass`, independent of
  // every pixel's and every other index's. Thread-safe.
  Rgb samplePoint(const Material& material, const Vec3& normal, const Vec3& x, uint64_t index, int pass) const;

  // Surfaces whose numbers come from the sequence; deeper ones use the stream.
  static constexpr int kSequenceBounces = 8;

 private:
  class PathNumbers;
  std::vector<uint32_t> passWords(uint32_t pass) const override;
  PixelSample sample(int x, int y, int pass, const std::vector<uint32_t>& words) const override;
  // E at x plus the reflected light, by the paths leaving x: B at x.
  Rgb radiosityAt(const Material& material, const Vec3& normal, const Vec3& x, const PathNumbers& u,
                  uint32_t& rays) const;
  const Material& materialOf(size_t polygon) const { return materials_[size_t(polygonMaterial_[polygon])]; }

  PathTraceSettings settings_;
  std::vector<Material> materials_;
  std::vector<int> polygonMaterial_;  // the material of each surface polygon
  std::unique_ptr<RayCaster> caster_;
  EmitterSampler emitters_;
  CameraRays cameraRays_;
  GatherSequence sequence_;
};

}  // namespace radview
