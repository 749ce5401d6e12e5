#pragma once
// Progressive refinement radiosity (Cohen, Chen, Wallace, Greenberg 1988), shooting from
// patches to mesh nodes with ray-traced element-to-node form factors (Wallace, Elmquist,
// Haines 1989), on a two-level hierarchy (Cohen, Greenberg, Immel, Brock 1986): the shooters are
// the patches, the elements of the initial mesh (or groups of them), never subdivided; the
// receivers are the nodes of the elements, which adaptive subdivision refines under the patches.
// A patch shoots the radiosity of each of its current elements, so that once its elements are
// subdivided it shoots at their resolution: a patch half in a shadow, or half under a block
// standing on it, shoots its lit part's light from its lit part only.
#include "discontinuity/discontinuity_events.h"
#include "geom/polygon.h"
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"
#include "solve/adaptive_subdivision.h"
#include "solve/element_to_node.h"
#include "trace/patch_sampler.h"
#include "trace/ray_caster.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace radview {

struct SolverSettings {
  uint64_t seed = 1;
  // Shooter samples per receiving node and shot, in batches: every node takes one batch; a node
  // that sees the shooter in part takes more, up to maxSamples, until the standard error of its
  // visible fraction is below visibilityError (element_to_node.h's VisibilitySampling).
  // maxSamples <= samples: one batch for every node. The defaults give the Cornell box's floor
  // a quarter of the noise of 16 samples everywhere, for about a third more time
  // (tests/bench/results/solution_noise.md).
  int samples = 32;
  int maxSamples = 256;
  double visibilityError = 0.01;
  double stopUnshotFraction = 0.01;  // stop once unshot power <= this * emitted power
  size_t maxShots = 100000;          // and after this many shots in any case
  bool quadratic = false;            // make the elements quadratic (mid-edge nodes) first
  // > 0: the initial elements are grouped into shooting patches of about this size
  // (shooting_patches.h), as a discontinuity mesh needs; 0: every initial element is a patch.
  double shooterSize = 0.0;
};

struct SolveProgress {
  size_t shots = 0;
  size_t patches = 0, elements = 0, nodes = 0;
  double unshotFraction = 1.0;  // unshot power / emitted power, summed over R, G, B
  uint64_t rays = 0;            // visibility rays cast so far (shooting and replay)
  double seconds = 0.0;         // time spent computing form factors (shooting and replay)
  double raysPerSecond() const { return seconds > 0.0 ? double(rays) / seconds : 0.0; }
};

// Power per channel (B times area) in the scene's units, for the energy balance
// emitted = absorbed + unshot (+ what leaves an open scene).
struct EnergyBalance {
  Rgb emitted{0.0};   // sum over elements of E A
  Rgb absorbed{0.0};  // sum over elements of (1 - rho) H A, H the mean gathered radiosity of its nodes
  Rgb unshot{0.0};    // sum over elements of their unshot radiosity times area
};

class ProgressiveRefinement {
 public:
  // `mesh`: any valid radiosity mesh of `scene` (elements on the scene's polygons, the scene's
  // materials), e.g. meshUniformly's or a discontinuity mesher's; its elements, or groups of
  // them (SolverSettings::shooterSize), become the patches. Throws Error when the mesh fails validateMesh or has no
  // element, when no element emits, or when a material's rho is not in [0, 1) or E is negative or not finite: rho = 1
  // would never absorb, so the solution would not converge.
  ProgressiveRefinement(const Scene& scene, RadiosityMesh mesh, const SolverSettings& settings);
  ~ProgressiveRefinement();

  // One shot from the patch of largest unshot power (summed over R, G, B, of the magnitudes of
  // its elements' unshot radiosities, which subdivision can make negative). Returns false,
  // shooting nothing, once the stop criterion is met.
  bool step();
  bool finished() const;

  // One round of adaptive subdivision of the elements (elementsToSplit on the current
  // solution), then the new nodes valued by replaying every shot so far (exactly the values
  // they would have had, had they existed from the start). Returns the elements split. The
  // children's radiosity, from their own nodes, differs from the parent's mean that was shot
  // for them: the difference is unshot (of either sign), and step() shoots it.
  size_t subdivide(const SubdivisionCriteria& criteria);

  const SolveProgress& progress() const { return progress_; }
  // The mesh with B = E + rho * (H + ambient) at every node; ambient is Cohen et al. 1988's
  // estimate of the light not yet shot (0 with withAmbient false, and for a converged solution
  // about 0): display only, the solution itself never includes it. Each node's standard error
  // is rho times the square root of H's variance: the noise of its own visibility estimates
  // (not that which the shooters carry from earlier bounces, nor the ambient term's bias).
  RadiosityMesh solution(bool withAmbient) const;
  // The ambient term per node: the radiosity the unshot light would still bring it.
  std::vector<Rgb> ambient() const;
  EnergyBalance energyBalance() const;
  // The zero-area polygons the ray caster left out.
  size_t ignoredPolygons() const { return rayCaster_->skippedPolygons(); }

 private:
  // A shooter: one element of the initial mesh, or a group of them (SolverSettings::
  // shooterSize), sampled over its current elements, each shooting its own unshot radiosity
  // (radiosityFromPatch).
  struct Patch {
    std::shared_ptr<const PatchSampler> sampler;  // its polygons: `elements`, in that order
    // Over its initial elements: the ambient term's patch-to-patch form factors, made once
    // whenever it is first asked for, are the same whatever the subdivision by then.
    std::shared_ptr<const PatchSampler> initial;
    std::vector<uint32_t> elements;
    Rgb rho{0.0};
    int surface = -1;
    // The centroid of its largest initial element: a point on the patch, which the centroid of
    // a grouped patch's polygons need not be.
    Vec3 centre{0.0};
  };
  struct Shot {
    uint32_t patch = 0;
    std::shared_ptr<const PatchSampler> sampler;  // the patch's elements when it shot
    std::vector<Rgb> deltaB;                      // per polygon of that sampler
  };

  void assignReceivers();
  // The mean gathered radiosity H of the element's nodes: what it reflects, rho times this, and
  // absorbs, (1 - rho) times this, per unit area (linear elements: the integral of the
  // interpolant over the element).
  Rgb meanH(uint32_t element, const std::vector<Rgb>& H) const;
  double unshotPower(const Patch& patch) const;  // sum over its elements of |unshot| A, R + G + B
  void makeSampler(Patch& patch) const;
  // The radiosity node gathers from shot, and its variance (radiosityFromPatch's standard error,
  // squared).
  Rgb gathered(size_t node, size_t shot, size_t& rays, std::vector<AreaSample>& scratch, Rgb& variance) const;
  VisibilitySampling visibilitySampling() const;
  void valueNewNodes(size_t firstNode);
  void updateUnshotFraction();
  void makePatchFormFactors() const;

  SolverSettings settings_;
  RadiosityMesh mesh_;
  MeshRefiner refiner_;
  std::unique_ptr<RayCaster> rayCaster_;
  std::vector<Vec3> surfaceNormals_;  // of the scene's polygons
  // Per scene polygon: its plane frame, and the outlines of the flat footprints on it
  // (findContacts' segments with a gap), near which assignReceivers moves the rays' start.
  std::vector<PlaneFrame> surfaceFrames_;
  std::vector<std::vector<EventSegment>> flatFootprints_;
  double sceneDiagonal_ = 0.0;
  std::vector<Patch> patches_;
  // Per element: its patch, its area, the radiosity it has shot (summed over its shots, a child
  // inheriting its parent's), and its unshot radiosity, E + rho meanH - shot (Cohen et al. 1988's
  // Delta B), kept up to date by step() and subdivide().
  std::vector<uint32_t> patchOf_;
  std::vector<double> elementArea_;
  std::vector<Rgb> shot_, unshot_;
  // Per node, from the first element that uses it: the point a hair inside that element its
  // rays leave from (ReceiverPoint::inside), the normal it receives with, its scene polygon, its
  // material (-1: no element uses it yet); and its gathered radiosity H, the sum of deltaB F
  // over the shots, so that B = E + rho H, and H's variance, summed over the shots (each shot's
  // rays from a node have a sample stream of their own).
  std::vector<Vec3> nodeInside_;
  std::vector<Vec3> nodeNormal_;
  std::vector<int> nodeSurface_;
  std::vector<int> nodeMaterial_;
  std::vector<Rgb> H_, varianceH_;
  std::vector<Shot> history_;
  double emittedPower_ = 0.0;  // sum over channels
  // [i * patches + j]: the form factor from patch i's centre to patch j with visibility, and
  // its visible fraction; made on first use (the ambient term), as the patches never change.
  mutable std::once_flag patchFormFactorsMade_;
  mutable std::vector<double> patchF_, patchVisibility_;
  SolveProgress progress_;
};

}  // namespace radview
