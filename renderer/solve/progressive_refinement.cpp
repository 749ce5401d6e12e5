#include "solve/progressive_refinement.h"

#include "core/error.h"
#include "core/parallel_for.h"
#include "geom/polygon.h"
#include "solve/element_to_node.h"
#include "solve/shooting_patches.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace radview {

namespace {

double channelSum(const Rgb& c) { return c.r + c.g + c.b; }

RadiosityMesh validated(RadiosityMesh mesh) {
  validateMesh(mesh, "radiosity mesh");
  if (mesh.elements.empty()) throw Error("the scene has no surface to solve (no element of non-zero area)");
  std::vector<char> used(mesh.materials.size(), 0);
  for (const Element& element : mesh.elements) used[element.material] = 1;
  const char* channel[3] = {"red", "green", "blue"};
  bool emits = false;
  for (size_t m = 0; m < mesh.materials.size(); ++m) {
    if (!used[m]) continue;
    const Material& material = mesh.materials[m];
    for (int k = 0; k < 3; ++k) {
      std::ostringstream problem;
      if (!(material.rho[k] >= 0.0 && material.rho[k] < 1.0))
        problem << "reflectance rho " << material.rho[k] << " in " << channel[k]
                << ": the solver needs 0 <= rho < 1 (a surface that absorbs nothing never lets the solution "
                   "converge)";
      else if (!(material.E[k] >= 0.0 && std::isfinite(material.E[k])))
        problem << "emission E " << material.E[k] << " in " << channel[k] << ": it must be finite and >= 0";
      if (!problem.str().empty())
        throw Error("material " + std::to_string(m) + " '" + material.name + "' has " + problem.str());
    }
    emits |= material.isEmitter();
  }
  if (!emits) throw Error("nothing emits light: no surface has a material with an emission E > 0");
  return mesh;
}

}  // namespace

ProgressiveRefinement::ProgressiveRefinement(const Scene& scene, RadiosityMesh mesh, const SolverSettings& settings)
    : settings_(settings),
      mesh_(validated(std::move(mesh))),
      refiner_(mesh_),
      rayCaster_(std::make_unique<RayCaster>(scene)) {
  for (const Polygon& polygon : scene.polygons) {
    surfaceNormals_.push_back(unitNormal(polygon.vertices));
    surfaceFrames_.push_back(surfaceNormals_.back() != Vec3(0.0) ? planeFrame(polygon.vertices) : PlaneFrame{});
  }
  for (std::vector<EventSegment>& contacts : findContacts(scene)) {
    contacts.erase(std::remove_if(contacts.begin(), contacts.end(),
                                  [](const EventSegment& contact) { return !(contact.gap > 0.0); }),
                   contacts.end());
    flatFootprints_.push_back(std::move(contacts));
  }
  sceneDiagonal_ = scene.bounds().diagonal();
  // Every element is its own patch, or a group of elements is (the first one's material and
  // surface, which the grouping shares).
  if (settings_.shooterSize > 0.0)
    patchOf_ = groupIntoShootingPatches(scene, mesh_, settings_.shooterSize);
  else
    for (uint32_t e = 0; e < mesh_.elements.size(); ++e) patchOf_.push_back(e);
  for (uint32_t e = 0; e < mesh_.elements.size(); ++e) {
    const Element& element = mesh_.elements[e];
    const Material& material = mesh_.materials[element.material];
    elementArea_.push_back(area(mesh_.cornerPositions(e)));
    if (patchOf_[e] == patches_.size()) {
      Patch patch;
      patch.rho = material.rho;
      patch.surface = element.surface;
      patches_.push_back(std::move(patch));
    }
    patches_[patchOf_[e]].elements.push_back(e);
    emittedPower_ += channelSum(material.E) * elementArea_.back();
  }
  for (Patch& patch : patches_) {
    const uint32_t largest =
        *std::max_element(patch.elements.begin(), patch.elements.end(),
                          [&](uint32_t a, uint32_t b) { return elementArea_[a] < elementArea_[b]; });
    patch.centre = centroid(mesh_.cornerPositions(largest));
    makeSampler(patch);
    patch.initial = patch.sampler;
  }
  shot_.assign(mesh_.elements.size(), Rgb(0.0));
  for (const Element& element : mesh_.elements) unshot_.push_back(mesh_.materials[element.material].E);
  if (settings_.quadratic) refiner_.makeQuadratic(mesh_);
  H_.assign(mesh_.nodes.size(), Rgb(0.0));
  varianceH_.assign(mesh_.nodes.size(), Rgb(0.0));
  assignReceivers();
  updateUnshotFraction();
  progress_.patches = patches_.size();
}

ProgressiveRefinement::~ProgressiveRefinement() = default;

void ProgressiveRefinement::makeSampler(Patch& patch) const {
  std::vector<std::vector<Vec3>> outlines;
  for (uint32_t e : patch.elements) outlines.push_back(mesh_.cornerPositions(e));
  patch.sampler = std::make_shared<const PatchSampler>(outlines, settings_.samples);
}

Rgb ProgressiveRefinement::meanH(uint32_t element, const std::vector<Rgb>& H) const {
  const Element& e = mesh_.elements[element];
  Rgb sum(0.0);
  for (const auto* list : {&e.corners, &e.midEdge})
    for (uint32_t node : *list) sum += H[node];
  return sum / double(e.corners.size() + e.midEdge.size());
}

double ProgressiveRefinement::unshotPower(const Patch& patch) const {
  double power = 0.0;
  for (uint32_t e : patch.elements)
    power += (std::abs(unshot_[e].r) + std::abs(unshot_[e].g) + std::abs(unshot_[e].b)) * elementArea_[e];
  return power;
}

// A node shared by elements of different surfaces (a mesh that welds across polygons) receives
// as its first element's surface, as solveDirectIllumination does. It receives at its own
// position, with a point a little way towards that element's centroid for what the position
// cannot give (ReceiverPoint::inside): a node on the edge where two walls meet lies in the
// other wall's plane, where the form factor to it is 0 by convention and its rays would graze
// that wall, but B is continuous there and takes the limit from inside the element (the wall
// then fills about half of its hemisphere). The step is twice the ray caster's lift, so the
// rays start in front of the other wall as surely as they end in front of it, or 1 % of the
// way for an element smaller than that; either way far below the element's size. Only rays and
// such edge-on form factors use it: the unoccluded form factor of every other node is taken at
// the node, where the interpolants put its value.
//
// A node within ten gaps of a flat footprint's outline (a light a hair under the ceiling,
// findContacts) has its rays leave from ten gaps further in, up to half way to the centroid:
// its true B climbs from half to all but 0.25 % of its value within those ten gaps, a step to
// its element, whose interpolant it spreads over the element were it valued at the outline.
void ProgressiveRefinement::assignReceivers() {
  nodeInside_.resize(mesh_.nodes.size(), Vec3(0.0));
  nodeNormal_.resize(mesh_.nodes.size(), Vec3(0.0));
  nodeSurface_.resize(mesh_.nodes.size(), -1);
  nodeMaterial_.resize(mesh_.nodes.size(), -1);
  for (uint32_t e = 0; e < mesh_.elements.size(); ++e) {
    const Element& element = mesh_.elements[e];
    const bool onSurface = element.surface >= 0 && element.surface < int(surfaceNormals_.size()) &&
                           surfaceNormals_[element.surface] != Vec3(0.0);
    const Vec3 normal = onSurface ? surfaceNormals_[element.surface] : mesh_.elementNormal(e);
    const Vec3 inside = centroid(mesh_.cornerPositions(e));
    for (const auto* list : {&element.corners, &element.midEdge})
      for (uint32_t node : *list) {
        if (nodeMaterial_[node] >= 0) continue;
        const Vec3 toInside = inside - mesh_.nodes[node].position;
        const double distance = glm::length(toInside);
        double step = distance > 0.0 ? std::min(0.01, 2.0 * RayCaster::kLift * sceneDiagonal_ / distance) : 0.0;
        if (onSurface && distance > 0.0) {
          const Vec2 p = surfaceFrames_[element.surface].project(mesh_.nodes[node].position);
          for (const EventSegment& outline : flatFootprints_[element.surface])
            if (distanceToSegment(p, outline.a, outline.b) < 10.0 * outline.gap)
              step = std::max(step, std::min(0.5, 10.0 * outline.gap / distance));
        }
        nodeInside_[node] = mesh_.nodes[node].position + step * toInside;
        nodeNormal_[node] = normal;
        nodeSurface_[node] = element.surface;
        nodeMaterial_[node] = element.material;
      }
  }
}

Rgb ProgressiveRefinement::gathered(size_t node, size_t shot, size_t& rays, std::vector<AreaSample>& scratch,
                                    Rgb& variance) const {
  variance = Rgb(0.0);
  const Shot& record = history_[shot];
  const Patch& shooter = patches_[record.patch];
  // A polygon does not light itself (it is planar): no rays for that.
  if (nodeMaterial_[node] < 0 || (shooter.surface >= 0 && nodeSurface_[node] == shooter.surface)) return Rgb(0.0);
  // Every (shot, node) pair has its own sample stream: the result is the same whichever thread
  // computes it, and a node made by subdivision replays exactly the samples it would have had.
  SampleStream stream = SampleStream::forKey(settings_.seed, shot, node);
  Rgb standardError(0.0);
  const Rgb H = radiosityFromPatch({mesh_.nodes[node].position, nodeNormal_[node], nodeInside_[node]},
                                   *record.sampler, record.deltaB, stream, rayCaster_.get(), rays, scratch,
                                   visibilitySampling(), &standardError);
  variance = standardError * standardError;
  return H;
}

VisibilitySampling ProgressiveRefinement::visibilitySampling() const {
  VisibilitySampling sampling;
  sampling.maxBatches = std::max(1, settings_.maxSamples / std::max(1, settings_.samples));
  sampling.targetError = settings_.visibilityError;
  return sampling;
}

bool ProgressiveRefinement::finished() const {
  return progress_.unshotFraction <= settings_.stopUnshotFraction || history_.size() >= settings_.maxShots ||
         !(progress_.unshotFraction > 0.0);
}

// Cohen et al. 1988, §2: shoot the patch with the most unshot power.
bool ProgressiveRefinement::step() {
  if (finished()) return false;
  uint32_t shooter = 0;
  double most = -1.0;
  for (uint32_t p = 0; p < patches_.size(); ++p) {
    const double power = unshotPower(patches_[p]);
    if (power > most) {
      most = power;
      shooter = p;
    }
  }
  Shot record{shooter, patches_[shooter].sampler, {}};
  for (uint32_t e : patches_[shooter].elements) {
    record.deltaB.push_back(unshot_[e]);
    shot_[e] += unshot_[e];
    unshot_[e] = Rgb(0.0);
  }
  history_.push_back(std::move(record));
  const size_t shot = history_.size() - 1;

  const auto start = std::chrono::steady_clock::now();
  std::vector<Rgb> deltaH(mesh_.nodes.size(), Rgb(0.0));
  // Rays counted per node and summed afterwards: one counter shared by the threads would be
  // written from every core for every node, and its cache line would bounce between them.
  std::vector<uint32_t> rays(mesh_.nodes.size(), 0);
  parallelFor(
      mesh_.nodes.size(),
      [&](size_t node) {
        thread_local std::vector<AreaSample> scratch;
        size_t cast = 0;
        Rgb variance(0.0);
        deltaH[node] = gathered(node, shot, cast, scratch, variance);
        H_[node] += deltaH[node];
        varianceH_[node] += variance;
        rays[node] = uint32_t(cast);
      },
      32);
  progress_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (uint32_t cast : rays) progress_.rays += cast;

  // What each element received, its nodes' mean, is new unshot radiosity (times rho) of that
  // element, which its patch shoots (Cohen et al. 1986's substructuring, at the elements'
  // resolution).
  for (uint32_t e = 0; e < mesh_.elements.size(); ++e)
    unshot_[e] += mesh_.materials[mesh_.elements[e].material].rho * meanH(e, deltaH);
  updateUnshotFraction();
  return true;
}

void ProgressiveRefinement::updateUnshotFraction() {
  double unshot = 0.0;
  for (const Patch& patch : patches_) unshot += unshotPower(patch);
  progress_.unshotFraction = emittedPower_ > 0.0 ? unshot / emittedPower_ : 0.0;
  progress_.shots = history_.size();
  progress_.elements = mesh_.elements.size();
  progress_.nodes = mesh_.nodes.size();
}

void ProgressiveRefinement::valueNewNodes(size_t firstNode) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<uint64_t> rays(mesh_.nodes.size() - firstNode, 0);  // per node, as in step()
  parallelFor(
      mesh_.nodes.size() - firstNode,
      [&](size_t i) {
        thread_local std::vector<AreaSample> scratch;
        const size_t node = firstNode + i;
        size_t cast = 0;
        Rgb H(0.0), varianceH(0.0), variance(0.0);
        for (size_t shot = 0; shot < history_.size(); ++shot) {
          H += gathered(node, shot, cast, scratch, variance);
          varianceH += variance;
        }
        H_[node] = H;
        varianceH_[node] = varianceH;
        rays[i] = cast;
      },
      4);
  progress_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (uint64_t cast : rays) progress_.rays += cast;
}

size_t ProgressiveRefinement::subdivide(const SubdivisionCriteria& criteria) {
  std::vector<uint32_t> chosen = elementsToSplit(solution(false), criteria);
  if (chosen.empty()) return 0;
  const size_t firstNode = mesh_.nodes.size();
  std::vector<uint32_t> parentOf;
  size_t split = refiner_.split(mesh_, chosen, parentOf);
  while (criteria.balance) {
    const std::vector<uint32_t> unbalanced = unbalancedElements(mesh_, criteria);
    const size_t more = unbalanced.empty() ? 0 : refiner_.split(mesh_, unbalanced, parentOf);
    if (more == 0) break;
    split += more;
    chosen.insert(chosen.end(), unbalanced.begin(), unbalanced.end());
  }
  // The children inherit what their parent shot; their patches are sampled over them from now
  // on (earlier shots keep the samplers they were shot with, for the replay).
  std::vector<char> changed(patches_.size(), 0);
  for (uint32_t parent : parentOf) {
    patchOf_.push_back(patchOf_[parent]);
    shot_.push_back(shot_[parent]);
  }
  for (uint32_t e : chosen) changed[patchOf_[e]] = 1;
  elementArea_.resize(mesh_.elements.size());
  for (uint32_t e : chosen) elementArea_[e] = area(mesh_.cornerPositions(e));
  for (size_t e = elementArea_.size() - parentOf.size(); e < elementArea_.size(); ++e)
    elementArea_[e] = area(mesh_.cornerPositions(e));
  for (Patch& patch : patches_) patch.elements.clear();
  for (uint32_t e = 0; e < mesh_.elements.size(); ++e) patches_[patchOf_[e]].elements.push_back(e);
  for (size_t p = 0; p < patches_.size(); ++p)
    if (changed[p]) makeSampler(patches_[p]);
  H_.resize(mesh_.nodes.size(), Rgb(0.0));
  varianceH_.resize(mesh_.nodes.size(), Rgb(0.0));
  assignReceivers();
  valueNewNodes(firstNode);
  // Every element's unshot radiosity from its nodes as they now are: its radiosity less what it
  // has shot (Cohen et al. 1988's Delta B).
  unshot_.resize(mesh_.elements.size());
  for (uint32_t e = 0; e < mesh_.elements.size(); ++e) {
    const Material& material = mesh_.materials[mesh_.elements[e].material];
    unshot_[e] = material.E + material.rho * meanH(e, H_) - shot_[e];
  }
  updateUnshotFraction();
  return split;
}

// The form factors between the patches, from each one's centre, with the visibility of the
// solve's own estimator (elementToNodeFormFactor), each pair with its own sample stream; and
// the fraction of each that is visible, F / F0 (1 where F0 is 0).
void ProgressiveRefinement::makePatchFormFactors() const {
  const size_t n = patches_.size();
  patchF_.assign(n * n, 0.0);
  patchVisibility_.assign(n * n, 1.0);
  parallelFor(
      n,
      [&](size_t i) {
        thread_local std::vector<AreaSample> scratch;
        const Patch& receiver = patches_[i];
        for (size_t j = 0; j < n; ++j) {
          if (j == i || (receiver.surface >= 0 && patches_[j].surface == receiver.surface)) continue;
          SampleStream stream = SampleStream::forKey(settings_.seed, UINT64_MAX, i * n + j);
          size_t rays = 0;
          const double F = elementToNodeFormFactor({receiver.centre, receiver.initial->normal()}, *patches_[j].initial,
                                                   stream, rayCaster_.get(), rays, scratch);
          const double F0 = patches_[j].initial->unoccluded().from(receiver.centre, receiver.initial->normal());
          patchF_[i * n + j] = F;
          if (F0 > 0.0) patchVisibility_[i * n + j] = F / F0;
        }
      },
      1);
}

// Cohen et al. 1988, §2.3's ambient term, the light not yet shot, estimated by where it goes
// rather than spread evenly: the paper's even spread gives every surface the same share, and
// over-brightens surfaces that the patches holding the unshot light barely see (a face turned
// away from the lit floor and walls). At the patches, the unshot radiosity U and what it brings
// after any number of bounces Y solve Y_i = rho_i sum_j F_ij (U_j + Y_j), the radiosity
// equation on the patches with the solve's visibility, by Jacobi iteration (C&W ch. 5). A node
// then gathers sum_j F_xj (U_j + Y_j): the exact unoccluded factor from the node, times the
// visible fraction of patch j seen from the centre of the patch the node lies in. A converged
// solution has U = 0 and gets 0.
std::vector<Rgb> ProgressiveRefinement::ambient() const {
  const size_t n = patches_.size();
  std::vector<Rgb> U(n, Rgb(0.0));  // area-weighted mean per patch
  for (size_t j = 0; j < n; ++j) {
    const Patch& patch = patches_[j];
    for (uint32_t e : patch.elements) U[j] += unshot_[e] * elementArea_[e];
    U[j] /= patch.sampler->area();
  }
  std::vector<Rgb> G(mesh_.nodes.size(), Rgb(0.0));
  if (std::all_of(U.begin(), U.end(), [](const Rgb& u) { return u == Rgb(0.0); })) return G;
  std::call_once(patchFormFactorsMade_, [this] { makePatchFormFactors(); });
  const std::vector<double>& F = patchF_;
  const std::vector<double>& visible = patchVisibility_;
  // Y converges as rho F's powers shrink (rho < 1, sum_j F_ij <= 1): stopped when a sweep adds
  // less than a millionth of the largest value.
  std::vector<Rgb> W = U, next(n);  // W = U + Y
  for (int sweep = 0; sweep < 1000; ++sweep) {
    double change = 0.0, largest = 0.0;
    for (size_t i = 0; i < n; ++i) {
      Rgb gathered(0.0);
      for (size_t j = 0; j < n; ++j) gathered += F[i * n + j] * W[j];
      next[i] = U[i] + patches_[i].rho * gathered;
      for (int k = 0; k < 3; ++k) {
        change = std::max(change, std::abs(next[i][k] - W[i][k]));
        largest = std::max(largest, next[i][k]);
      }
    }
    W.swap(next);
    if (change <= 1e-6 * largest) break;
  }
  // The patch each node receives in: that of the first element that uses it, as assignReceivers.
  std::vector<uint32_t> patchOf(mesh_.nodes.size(), UINT32_MAX);
  for (uint32_t e = 0; e < mesh_.elements.size(); ++e)
    for (const auto* list : {&mesh_.elements[e].corners, &mesh_.elements[e].midEdge})
      for (uint32_t node : *list)
        if (patchOf[node] == UINT32_MAX) patchOf[node] = patchOf_[e];
  parallelFor(
      mesh_.nodes.size(),
      [&](size_t node) {
        if (nodeMaterial_[node] < 0) return;
        const Vec3& x = mesh_.nodes[node].position;
        const size_t p = patchOf[node];
        for (size_t j = 0; j < n; ++j) {
          const Patch& shooter = patches_[j];
          if (W[j] == Rgb(0.0) || (shooter.surface >= 0 && nodeSurface_[node] == shooter.surface)) continue;
          // At the inside point where the shooter is edge-on to the node, as gathered() does.
          double F0 = shooter.sampler->unoccluded().from(x, nodeNormal_[node]);
          if (F0 == 0.0) F0 = shooter.sampler->unoccluded().from(nodeInside_[node], nodeNormal_[node]);
          if (F0 == 0.0) continue;
          G[node] += F0 * visible[p * n + j] * W[j];
        }
      },
      32);
  return G;
}

RadiosityMesh ProgressiveRefinement::solution(bool withAmbient) const {
  RadiosityMesh result = mesh_;
  result.hasGradients = false;
  result.hasStandardErrors = true;
  const std::vector<Rgb> extra = withAmbient ? ambient() : std::vector<Rgb>(mesh_.nodes.size(), Rgb(0.0));
  for (size_t node = 0; node < result.nodes.size(); ++node) {
    if (nodeMaterial_[node] < 0) continue;
    const Material& material = mesh_.materials[nodeMaterial_[node]];
    result.nodes[node].B = material.E + material.rho * (H_[node] + extra[node]);
    result.nodes[node].standardError = material.rho * glm::sqrt(varianceH_[node]);
    result.nodes[node].gradient = {};
  }
  return result;
}

EnergyBalance ProgressiveRefinement::energyBalance() const {
  EnergyBalance balance;
  for (uint32_t e = 0; e < mesh_.elements.size(); ++e) {
    const Material& material = mesh_.materials[mesh_.elements[e].material];
    balance.emitted += material.E * elementArea_[e];
    balance.unshot += unshot_[e] * elementArea_[e];
    balance.absorbed += (Rgb(1.0) - material.rho) * meanH(e, H_) * elementArea_[e];
  }
  return balance;
}

}  // namespace radview
