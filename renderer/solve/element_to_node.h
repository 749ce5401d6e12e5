#pragma once
// The element-to-node form factor of ray-traced progressive radiosity (Wallace, Elmquist,
// Haines 1989): the form factor from a point (a mesh node) to a shooting patch, with the
// patch's visibility from the point estimated by rays to samples of its area.
#include "core/types.h"
#include "trace/patch_sampler.h"
#include "trace/ray_caster.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace radview {

struct ReceiverPoint {
  Vec3 position;
  Vec3 normal;  // unit, the side that receives
  // A point a hair inside the receiving element (unset: `position` itself). The visibility rays
  // leave from it, so that rays from a node on the edge two walls share do not graze the other
  // wall. F0 is taken there only where it is 0 at `position`: on the shooter's plane, where 0
  // is the edge-on convention and B's value is the limit from inside the element. Everywhere
  // else F0 is taken at `position` itself, so that an unoccluded node gets B at the node.
  std::optional<Vec3> inside = std::nullopt;
};

// How many of a shooter's samples a node's visibility takes: batches of the sampler's samples()
// (one stratified set each). A node whose first batch is all visible or all hidden is settled
// by it (C&W §4.9.2's samples are spent where the answer is uncertain: the penumbrae); one that
// sees the shooter in part takes at least minBatches, then more until the standard error of its
// estimate is below `targetError` of the unoccluded value, or maxBatches. maxBatches 1 is one
// batch everywhere.
struct VisibilitySampling {
  int maxBatches = 1;
  int minBatches = 4;
  double targetError = 0.0;  // relative to the node's unoccluded F0 B
};

// F(dA_x -> A_i) = F0 * (sum_k K_k V_k) / (sum_k K_k), F0 the exact unoccluded point-to-polygon
// form factor (PatchFormFactor) and the fraction its visible share, estimated over the
// shooter's samples k, each weighted by its share of the kernel, K_k = w_k cos(theta_x)
// cos(theta_k) / r_k^2 (C&W §4.9.2: the analytic unoccluded factor times ray-cast visibility).
//
// A departure from Wallace et al.'s estimator, sum_k w_k cos cos V_k / (pi r_k^2 + w_k): their
// disc term w_k biases the estimate low wherever the receiver is within about a sample spacing
// of the shooter. At a node on the edge two walls share it gives 0 instead of 1/2 (measured on
// unit squares: -7.5 % on Howell's perpendicular-squares factor at 256 samples), which would
// darken every corner of a room. This one is exact where nothing occludes, so the noise of
// the samples shows only in penumbrae.
//
// Samples behind the receiver or the shooter cast no ray; no ray is cast when F0 is 0.
// `visibility` null: nothing occludes (V = 1). `rays` is increased by the rays cast. `scratch`
// is reused between calls. With several batches (`sampling`), the estimate pools them all, and
// `standardError`, when given, receives its standard error from the spread of the batches' own
// estimates. Where one batch is all it takes (a node that sees the shooter wholly or not at all,
// or maxBatches 1), it is that batch's own spread, taken as if its samples were independent:
// 0 for a settled node shot by one radiosity, an upper bound for a stratified set seen in part.
double elementToNodeFormFactor(const ReceiverPoint& x, const PatchSampler& shooter, SampleStream& stream,
                               const RayCaster* visibility, size_t& rays, std::vector<AreaSample>& scratch,
                               const VisibilitySampling& sampling = {}, double* standardError = nullptr);

// The radiosity x gathers from a shooter whose polygons shoot different radiosities B_p (a
// patch grouping several elements, shooting_patches.h): F0 * (sum_k K_k V_k B_p(k)) / (sum_k K_k),
// the same estimator with each sample carrying its polygon's radiosity. It is
// elementToNodeFormFactor times B where every B_p is B, and otherwise keeps what each polygon
// shoots where it is, at the resolution of the samples (with one B for the whole patch, a
// shadowed part of it would shoot the lit part's light). `polygonB` has one entry per polygon
// the sampler was built from.
Rgb radiosityFromPatch(const ReceiverPoint& x, const PatchSampler& shooter, const std::vector<Rgb>& polygonB,
                       SampleStream& stream, const RayCaster* visibility, size_t& rays,
                       std::vector<AreaSample>& scratch, const VisibilitySampling& sampling = {},
                       Rgb* standardError = nullptr);

}  // namespace radview
