#include "interp/thin_plate.h"

#include "core/disjoint_sets.h"
#include "core/error.h"
#include "core/parallel_for.h"
#include "core/strings.h"
#include "interp/thin_plate_region.h"
#include "mesh/display_mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace radview {

namespace {

// The elements of one surface joined through shared nodes. Elements of unknown surface (-1)
// join when their planes agree.
std::vector<std::vector<uint32_t>> findRegions(const RadiosityMesh& mesh) {
  const size_t count = mesh.elements.size();
  std::vector<std::pair<uint32_t, uint32_t>> uses;  // (node, element)
  for (uint32_t e = 0; e < count; ++e)
    for (const auto* list : {&mesh.elements[e].corners, &mesh.elements[e].midEdge})
      for (uint32_t node : *list) uses.push_back({node, e});
  std::sort(uses.begin(), uses.end());
  std::vector<Vec3> normals(count, Vec3(0.0));
  for (uint32_t e = 0; e < count; ++e)
    if (mesh.elements[e].surface < 0) normals[e] = mesh.elementNormal(e);
  auto together = [&](uint32_t a, uint32_t b) {
    const int sa = mesh.elements[a].surface, sb = mesh.elements[b].surface;
    if (sa >= 0 || sb >= 0) return sa == sb;
    return glm::dot(normals[a], normals[b]) > 0.9999;
  };
  DisjointSets<uint32_t> sets(count);
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    while (j < uses.size() && uses[j].first == uses[i].first) ++j;
    for (size_t a = i; a < j; ++a)
      for (size_t b = i; b < a; ++b)
        if (together(uses[a].second, uses[b].second)) sets.join(uses[a].second, uses[b].second);
    i = j;
  }
  std::vector<std::vector<uint32_t>> regions;
  std::vector<uint32_t> regionOf(count, UINT32_MAX);
  for (uint32_t e = 0; e < count; ++e) {
    uint32_t& region = regionOf[sets.find(e)];
    if (region == UINT32_MAX) {
      region = uint32_t(regions.size());
      regions.emplace_back();
    }
    regions[region].push_back(e);
  }
  return regions;
}

// 1 / (SE^2 + s0^2), s0 half the region's RMS standard error (luminance); empty without
// standard errors, or where all of them are 0.
Eigen::VectorXd inverseVariances(const RadiosityMesh& mesh, const std::vector<uint32_t>& nodes) {
  const Eigen::Index n = Eigen::Index(nodes.size());
  if (!mesh.hasStandardErrors) return {};
  Eigen::VectorXd variance(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Rgb& e = mesh.nodes[nodes[size_t(i)]].standardError;
    const double luminance = 0.2126 * e.r + 0.7152 * e.g + 0.0722 * e.b;
    variance(i) = luminance * luminance;
  }
  const double floor = 0.25 * variance.mean();
  if (!(floor > 0.0)) return {};
  return (variance.array() + floor).inverse().matrix();
}

}  // namespace

ThinPlateSettings thinPlateSettingsFromText(const std::string& text) {
  ThinPlateSettings settings;
  if (text == "auto") return settings;
  const std::optional<double> lambda = parseFiniteNumber(text);
  if (!lambda || !(*lambda >= 0.0))
    throw Error("--smoothing '" + text + "': expected auto or a lambda >= 0 (a finite number)");
  settings.lambda = *lambda;
  return settings;
}

RadiosityMesh smoothThinPlate(const RadiosityMesh& mesh, const MeshTopology& topology,
                              const ThinPlateSettings& settings, ThinPlateReport* report,
                              const std::vector<double>* weights) {
  if (settings.lambda && !(*settings.lambda >= 0.0 && std::isfinite(*settings.lambda))) {
    std::ostringstream message;
    message << "thin-plate smoothing " << *settings.lambda << ": expected a finite lambda >= 0";
    throw Error(message.str());
  }
  if (weights) {
    if (weights->size() != mesh.nodes.size())
      throw Error("thin-plate weights: " + std::to_string(weights->size()) + " for " +
                  std::to_string(mesh.nodes.size()) + " nodes");
    for (size_t i = 0; i < weights->size(); ++i)
      if (!((*weights)[i] >= 0.0 && std::isfinite((*weights)[i]))) {
        std::ostringstream message;
        message << "thin-plate weights: node " << i << " has weight " << (*weights)[i]
                << " (expected finite and >= 0)";
        throw Error(message.str());
      }
  }
  std::vector<uint64_t> untouchable;  // edges tagged C0 or C-1: no bending energy across them
  for (const DiscontinuityEdge& d : mesh.discontinuities)
    if (d.order != Continuity::C1) untouchable.push_back(edgeKey(d.a, d.b));
  std::sort(untouchable.begin(), untouchable.end());
  const std::vector<std::vector<TVertex>> tVertices = tVerticesByElement(mesh, topology);
  const std::vector<std::vector<uint32_t>> regions = findRegions(mesh);

  std::vector<RegionProblem> problems(regions.size());
  std::vector<RegionFit> fits(regions.size());
  std::vector<ThinPlateRegion> summaries(regions.size());
  // Largest regions first: the cores take the next region as they finish one, and a large one
  // left for last would keep one core busy alone.
  std::vector<size_t> largestFirst(regions.size());
  std::iota(largestFirst.begin(), largestFirst.end(), size_t(0));
  std::stable_sort(largestFirst.begin(), largestFirst.end(),
                   [&](size_t a, size_t b) { return regions[a].size() > regions[b].size(); });
  parallelFor(
      regions.size(),
      [&](size_t i) {
        const size_t r = largestFirst[i];
        RegionProblem& problem = problems[r];
        // Local node indices, and the region's triangles over them (T-vertices made corners, so
        // that the triangulation is conforming).
        thread_local std::vector<int32_t> local;
        local.resize(mesh.nodes.size(), -1);
        std::vector<std::array<uint32_t, 3>>& triangles = problem.triangles;
        auto localOf = [&](uint32_t node) {
          if (local[node] < 0) {
            local[node] = int32_t(problem.nodes.size());
            problem.nodes.push_back(node);
          }
          return uint32_t(local[node]);
        };
        for (uint32_t e : regions[r])
          for (const auto& t : watertightTriangles(mesh, e, tVertices[e]))
            triangles.push_back({localOf(t[0].node), localOf(t[1].node), localOf(t[2].node)});
        for (uint32_t e : regions[r])
          for (const auto* list : {&mesh.elements[e].corners, &mesh.elements[e].midEdge})
            for (uint32_t node : *list) localOf(node);
        for (uint64_t key : untouchable) {
          const uint32_t a = uint32_t(key >> 32), b = uint32_t(key);
          if (local[a] >= 0 && local[b] >= 0) problem.untouchable.push_back(edgeKey(uint32_t(local[a]), uint32_t(local[b])));
        }
        std::sort(problem.untouchable.begin(), problem.untouchable.end());
        for (uint32_t node : problem.nodes) problem.positions.push_back(mesh.nodes[node].position);
        for (uint32_t node : problem.nodes) local[node] = -1;
        const Eigen::Index n = Eigen::Index(problem.nodes.size());
        problem.values = Eigen::MatrixXd(n, 3);
        for (Eigen::Index i = 0; i < n; ++i)
          for (int c = 0; c < 3; ++c) problem.values(i, c) = mesh.nodes[problem.nodes[size_t(i)]].B[c];
        if (weights) {
          problem.weights = Eigen::VectorXd(n);
          for (Eigen::Index i = 0; i < n; ++i) problem.weights(i) = (*weights)[problem.nodes[size_t(i)]];
        } else {
          problem.inverseVariance = inverseVariances(mesh, problem.nodes);
          problem.weights = problem.inverseVariance.size() > 0
                                ? Eigen::VectorXd(problem.inverseVariance / problem.inverseVariance.mean())
                                : Eigen::VectorXd::Ones(n);
        }
        const Element& first = mesh.elements[regions[r].front()];
        ThinPlateRegion& summary = summaries[r];
        summary.nodes = problem.nodes.size();
        summary.surface = first.surface;
        if (!mesh.materials[first.material].isEmitter()) setBendingEnergy(problem);
        fits[r] = fitRegion(problem, settings);
        summary.lambda = fits[r].lambda;
        summary.effectiveDof = fits[r].effectiveDof;
        summary.smoothed = fits[r].smoothed;
        std::vector<uint32_t> nodes = std::move(problem.nodes);
        problem = RegionProblem{};  // all but the node list freed as soon as fitted
        problem.nodes = std::move(nodes);
      },
      1);

  RadiosityMesh out = mesh;
  out.hasGradients = false;
  out.hasStandardErrors = false;
  std::vector<Rgb> sum(mesh.nodes.size(), Rgb(0.0));
  std::vector<uint32_t> count(mesh.nodes.size(), 0);
  for (size_t r = 0; r < regions.size(); ++r)
    for (size_t i = 0; i < problems[r].nodes.size(); ++i) {
      const uint32_t node = problems[r].nodes[i];
      for (int c = 0; c < 3; ++c) sum[node][c] += fits[r].values(Eigen::Index(i), c);
      ++count[node];
    }
  for (size_t node = 0; node < out.nodes.size(); ++node) {
    out.nodes[node].gradient = {};
    out.nodes[node].standardError = Rgb(0.0);
    if (count[node] > 0) out.nodes[node].B = sum[node] / double(count[node]);
  }
  if (report) report->regions = std::move(summaries);
  return out;
}

}  // namespace radview
