#pragma once
// The two-pass method's second pass (C&W §9.3.1, eq. 9.9): for the point x_p seen through each
// pixel,
//   B(x_p) = E(x_p) + rho(x_p) * integral over the surfaces of B^(x') G(x_p, x') dA',
// with B^ the radiosity solution reconstructed by one of the interpolants of §9.2 and G
// including visibility, estimated by Monte Carlo with rays cast through Embree. The last bounce,
// and with it every shadow, is resolved at image resolution: radview's accuracy reference for
// what the interpolants show directly.
//
// The estimator, per pixel and pass (one sample per pixel per pass):
//  - the eye ray through a uniformly jittered point of the pixel (so the mean antialiases;
//    alpha is the fraction of samples that see a surface), or through its centre;
//  - at a fixed point (GatherPoint: the pixel's centre, as the bench takes it), both parts of the
//    integral with control variates (control_variates.h): a stand-in for the scene whose
//    integral, shadows included, is known in closed form, and only the difference is sampled;
//  - direct light: emitterSamples points on the emitters (EmitterSampler, by power, one-sided),
//    E_e cos(theta_p) cos(theta_e) / (pi r^2) V / pdf each, less the control's;
//  - indirect light: cosine-weighted directions (several at a fixed point), each contributing
//    B^(x') - E(x') at the surface it meets (the pdf cos / pi cancels G's cos / pi) less the
//    control's value in that direction. Emission is left out there because the emitters are
//    sampled explicitly: counting it twice would double the direct light.
//
// Decisions where the book is silent:
//  - Surfaces are one-sided, as the solver treats them (a polygon seen from behind has form
//    factor 0): an indirect ray that meets a back face gathers nothing from it (and stops
//    there), and emitters emit on their front side only.
//  - An eye ray that sees a back face shows B^ there, not gathered: the solution holds no
//    radiosity for the back side, and B^ is what the GL renderer draws on both sides (it does
//    not cull), so the two images stay comparable everywhere.
//  - E(x_p) is the material's emission, added exactly (an emitter's own pixels are its E plus
//    the light it reflects).
//  - B^ is not clamped at zero where a higher-order interpolant overshoots below it: eq. 9.9
//    integrates B^ as it is, and overshoot comes in pairs (below zero beside a peak above the
//    data), so clamping only the negative side would add energy and bias the reference.
//
// The numbers a sample draws are pass `pass`'s point of a GatherSequence, shifted by the
// pixel's own word per coordinate: coordinates 0-1 the indirect directions (the sequence's best
// stratified pair, for the integrand that varies most: at a fixed point, direction j of pass p
// takes point k p + j there), 2-3 the point in the pixel, then four per emitter sample (the
// emitter, the point on it, whether its shadow ray is cast). Each pixel's samples do not depend
// on which thread takes them, so the image is bit-identical for any thread count.
#include "core/camera.h"
#include "core/image.h"
#include "gather/control_variates.h"
#include "gather/emitter_sampler.h"
#include "gather/gather_sequence.h"
#include "gather/progressive_image.h"
#include "interp/interpolant.h"
#include "mesh/radiosity_mesh.h"
#include "trace/camera_rays.h"
#include "trace/ray_caster.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace radview {

struct GatherSettings {
  Method interpolant = Method::Gouraud;  // B^ under the integral
  InterpolantOptions interpolantOptions;
  uint64_t seed = 1;
  int width = 256, height = 256;
  Camera camera;
  int emitterSamples = 1;  // shadow rays per pixel per pass
  // Independent runs of the estimator, each with sample sequences of its own: pass p belongs to
  // run p mod runs. Their spread estimates the image's noise (bench/error_estimate.h).
  int runs = 1;
  // Every sample through the pixel's centre, where the GL renderer evaluates a method, instead
  // of a point jittered over the pixel (which antialiases silhouettes): the bench's reference.
  bool pixelCentres = false;
};
// Equal settings make the same image (of the same mesh): every field, the camera's included.
bool operator==(const GatherSettings& a, const GatherSettings& b);
inline bool operator!=(const GatherSettings& a, const GatherSettings& b) { return !(a == b); }

// A surface point eq. 9.9 is estimated at, seen from the front of its element. A fixed point
// (gatherPoint: a pixel's centre, a node) takes every pass, so what it costs once pays off: it
// carries the controls' integrals there, and each pass samples several indirect directions. A
// point that one sample alone sees (a jittered eye ray) is estimated plainly: no controls, one
// direction, every shadow ray cast.
struct GatherPoint {
  uint32_t element = 0;
  Vec3 position{0.0};
  bool fixed = false;
  Rgb controlled{0.0};  // fixed: the controls' integrals (SceneControl::integral)
  uint64_t facing = 0;  // fixed: the hulls in front of it (SceneControl::facing)
};

class FinalGather : public ProgressiveImage {
 public:
  // The mesh must outlive the gather. Throws Error for a size below 1x1, emitterSamples below 1,
  // or an interpolant the mesh cannot support.
  FinalGather(const RadiosityMesh& mesh, const GatherSettings& settings);

  const GatherSettings& settings() const { return settings_; }

  // A fixed surface point x of `element`, seen from its front, with the controls' integrals
  // there (a clipped Lambert sum per hull: form it once for all its samples). Thread-safe.
  GatherPoint gatherPoint(uint32_t element, const Vec3& x) const;
  // Sample number `pass` of eq. 9.9 at that point, its numbers those of point `index` (of the
  // gather's run pass mod runs): independent of every pixel's and every other index's.
  // Thread-safe.
  Rgb samplePoint(const GatherPoint& point, uint64_t index, int pass) const;

 private:
  std::vector<uint32_t> passWords(uint32_t pass) const override;
  PixelSample sample(int x, int y, int pass, const std::vector<uint32_t>& point) const override;
  // What each pixel's centre sees, and its fixed point, cast once (pixelCentres).
  void prepare() override;
  Rgb radiosityAt(const GatherPoint& point, const GatherSequence::PixelPoint& u, uint32_t& rays) const;
  // What pixel (x, y)'s centre sees: cast once, at the first pass (pixelCentres).
  std::optional<RayHit> centreHit(int x, int y) const;
  // The parts of the direct and indirect light the controls leave to sampling.
  Rgb directResidual(const GatherPoint& point, const Vec3& n, const GatherSequence::PixelPoint& u,
                     uint32_t& rays) const;
  Rgb indirectResidual(const GatherPoint& point, const Vec3& n, const GatherSequence::PixelPoint& u,
                       uint32_t& rays) const;

  const RadiosityMesh& mesh_;
  GatherSettings settings_;
  std::unique_ptr<Interpolant> interpolant_;
  std::unique_ptr<RayCaster> caster_;  // over the mesh's elements: polygon i is element i
  std::vector<Vec3> normals_;          // unit normal of each element
  EmitterSampler emitters_;
  SceneControl control_;
  CameraRays cameraRays_;
  GatherSequence sequence_;
  std::vector<std::optional<RayHit>> centreHits_;  // per pixel, with pixelCentres
  std::vector<GatherPoint> centrePoints_;          // of each front hit, with pixelCentres
};

}  // namespace radview
