#include "bench/nodal_reference.h"

#include "core/error.h"
#include "core/parallel_for.h"
#include "trace/ray_caster.h"

#include <algorithm>

#include <limits>

namespace radview {

RadiosityMesh NodalReference::withRun(const RadiosityMesh& mesh, int run) const {
  RADVIEW_CHECK(run >= 0 && run < runs && B.size() == mesh.nodes.size() * size_t(runs));
  RadiosityMesh copy = mesh;
  for (size_t n = 0; n < copy.nodes.size(); ++n) copy.nodes[n].B = B[n * size_t(runs) + size_t(run)];
  return copy;
}

std::vector<char> nodesOfTheView(const RadiosityMesh& mesh, const std::vector<int32_t>& elementAt) {
  std::vector<char> seen(mesh.elements.size(), 0), node(mesh.nodes.size(), 0);
  for (int32_t e : elementAt)
    if (e >= 0) seen[size_t(e)] = 1;
  auto nodesOf = [&](size_t e, auto&& visit) {
    for (const auto* nodes : {&mesh.elements[e].corners, &mesh.elements[e].midEdge})
      for (uint32_t n : *nodes) visit(n);
  };
  for (size_t e = 0; e < mesh.elements.size(); ++e)
    if (seen[e]) nodesOf(e, [&](uint32_t n) { node[n] = 1; });
  std::vector<char> wanted = node;
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    bool touches = false;
    nodesOf(e, [&](uint32_t n) { touches = touches || node[n]; });
    if (touches) nodesOf(e, [&](uint32_t n) { wanted[n] = 1; });
  }
  return wanted;
}

namespace {

// `samplesPerRun` samples per run at each node `wanted` says, `samplerAt(element, x, node)`
// giving a node's sampler: a callable from the pass number to one estimate of B at x.
template <class SamplerAt>
NodalReference estimateAtNodes(const RadiosityMesh& mesh, int runs, int samplesPerRun, const std::vector<char>& wanted,
                               const SamplerAt& samplerAt) {
  RADVIEW_CHECK(wanted.empty() || wanted.size() == mesh.nodes.size());
  constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> elementOf(mesh.nodes.size(), kNone);
  for (size_t e = 0; e < mesh.elements.size(); ++e)
    for (const auto* nodes : {&mesh.elements[e].corners, &mesh.elements[e].midEdge})
      for (uint32_t n : *nodes)
        if (elementOf[n] == kNone) elementOf[n] = uint32_t(e);
  const double lift = RayCaster::kLift * mesh.bounds().diagonal();
  NodalReference reference;
  reference.runs = runs;
  reference.B.resize(mesh.nodes.size() * size_t(runs));
  parallelFor(
      mesh.nodes.size(),
      [&](size_t n) {
        const uint32_t element = elementOf[n];
        for (int r = 0; r < runs; ++r) reference.B[n * size_t(runs) + size_t(r)] = mesh.nodes[n].B;
        if (element == kNone || (!wanted.empty() && !wanted[n])) return;
        Vec3 centroid(0.0);
        for (uint32_t c : mesh.elements[element].corners) centroid += mesh.nodes[c].position;
        centroid /= double(mesh.elements[element].corners.size());
        // Far enough in that the rays' lift off the surface (RayCaster::kLift) cannot carry them
        // across the element's edge to the other side of a discontinuity, and no further than
        // needed: 1e-3 of the way to the centroid, at least 20 lifts, at most half-way.
        const Vec3 inward = centroid - mesh.nodes[n].position;
        const double length = glm::length(inward);
        if (!(length > 0.0)) return;
        const double step = std::min(0.5 * length, std::max(1e-3 * length, 20.0 * lift));
        const Vec3 x = mesh.nodes[n].position + inward * (step / length);
        const auto sample = samplerAt(element, x, uint64_t(n));
        for (int r = 0; r < runs; ++r) {
          Rgb sum(0.0);
          for (int p = 0; p < samplesPerRun; ++p) sum += sample(p * runs + r);
          reference.B[n * size_t(runs) + size_t(r)] = sum / double(samplesPerRun);
        }
      },
      16);
  return reference;
}

}  // namespace

NodalReference gatherAtNodes(const RadiosityMesh& mesh, const FinalGather& gather, int samplesPerRun,
                             const std::vector<char>& wanted) {
  return estimateAtNodes(mesh, gather.settings().runs, samplesPerRun, wanted,
                         [&](uint32_t element, const Vec3& x, uint64_t node) {
                           return [&gather, point = gather.gatherPoint(element, x), node](int pass) {
                             return gather.samplePoint(point, node, pass);
                           };
                         });
}

NodalReference pathTraceAtNodes(const RadiosityMesh& mesh, const PathTracer& tracer, int samplesPerRun,
                                const std::vector<char>& wanted) {
  return estimateAtNodes(mesh, tracer.settings().runs, samplesPerRun, wanted,
                         [&](uint32_t element, const Vec3& x, uint64_t node) {
                           const Material& material = mesh.materials[size_t(mesh.elements[element].material)];
                           return [&tracer, &material, normal = mesh.elementNormal(element), x, node](int pass) {
                             return tracer.samplePoint(material, normal, x, node, pass);
                           };
                         });
}

}  // namespace radview
