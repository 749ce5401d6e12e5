#include "interp/thin_plate.h"

#include "core/disjoint_sets.h"
#include "core/error.h"
#include "core/parallel_for.h"
#include "core/strings.h"
#include "interp/nested_dissection.h"
#include "mesh/display_mesh.h"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <sstream>

namespace radview {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

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

uint64_t edgeKey(uint32_t a, uint32_t b) { return uint64_t(std::min(a, b)) << 32 | std::max(a, b); }

// One region's fitting problem: its nodes, their values and weights, and Q, the bending energy's
// matrix (E(f) = f^T Q f) over its local node indices.
struct RegionProblem {
  std::vector<uint32_t> nodes;
  Eigen::MatrixXd values;  // nodes x 3
  Eigen::VectorXd weights;
  // With standard errors: 1 / (SE^2 + s0^2) of the luminance, not rescaled (the discrepancy
  // check's yardstick); empty without them.
  Eigen::VectorXd inverseVariance;
  SparseMatrix Q;
  size_t bendingEdges = 0;
  std::vector<Vec3> positions;  // the nodes'
};

// The normal-derivative jumps across the region's interior edges (thin_plate.h), as rows of
// Q = sum_e c_e d_e d_e^T.
SparseMatrix bendingEnergy(const std::vector<std::array<uint32_t, 3>>& triangles,
                           const std::vector<uint64_t>& untouchable, size_t nodeCount,
                           const std::vector<Vec3>& positions, size_t& rows) {
  struct Side {
    uint64_t key;
    uint32_t triangle;
    int opposite;  // the corner of the triangle not on the edge
  };
  std::vector<Side> sides;
  sides.reserve(3 * triangles.size());
  std::vector<std::array<Vec3, 3>> gradients(triangles.size());  // of the three hat functions
  std::vector<double> areas(triangles.size(), 0.0);
  std::vector<Vec3> normals(triangles.size(), Vec3(0.0));
  for (uint32_t t = 0; t < triangles.size(); ++t) {
    const auto& v = triangles[t];
    const Vec3 cross = glm::cross(positions[v[1]] - positions[v[0]], positions[v[2]] - positions[v[0]]);
    const double twiceArea = glm::length(cross);
    if (!(twiceArea > 0.0)) continue;  // no gradient: left out of the energy
    areas[t] = 0.5 * twiceArea;
    normals[t] = cross / twiceArea;
    // grad phi_k = N x (x_{k+2} - x_{k+1}) / 2A: towards corner k, across the opposite edge.
    for (int k = 0; k < 3; ++k)
      gradients[t][k] = glm::cross(normals[t], positions[v[(k + 2) % 3]] - positions[v[(k + 1) % 3]]) / twiceArea;
    for (int k = 0; k < 3; ++k) sides.push_back({edgeKey(v[(k + 1) % 3], v[(k + 2) % 3]), t, k});
  }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) { return a.key < b.key; });
  // D, one row per interior edge: the jump's coefficients scaled by sqrt(c_e), so that
  // Q = D^T D. Its rows hold four nodes (the two triangles share the edge's two), where Q's
  // products of them would be sixteen, and summing duplicates first keeps D small.
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(3 * sides.size());
  rows = 0;
  for (size_t i = 0; i + 1 < sides.size(); ++i) {
    if (sides[i].key != sides[i + 1].key || (i + 2 < sides.size() && sides[i + 2].key == sides[i].key)) continue;
    if (std::binary_search(untouchable.begin(), untouchable.end(), sides[i].key)) continue;
    const Side& s1 = sides[i];
    const Side& s2 = sides[i + 1];
    const auto& v1 = triangles[s1.triangle];
    const auto& v2 = triangles[s2.triangle];
    const Vec3 a = positions[v1[(s1.opposite + 1) % 3]], b = positions[v1[(s1.opposite + 2) % 3]];
    // In each triangle's plane, the unit vector across the edge away from its own interior: the
    // two derivatives along them sum to the jump, also where the surface folds.
    auto outward = [&](uint32_t t, int opposite) {
      Vec3 m = glm::normalize(glm::cross(normals[t], b - a));
      if (glm::dot(m, positions[triangles[t][opposite]] - a) > 0.0) m = -m;
      return m;
    };
    const Vec3 m1 = outward(s1.triangle, s1.opposite), m2 = outward(s2.triangle, s2.opposite);
    const double length2 = glm::dot(b - a, b - a);
    const double root = std::sqrt(2.0 * length2 / (areas[s1.triangle] + areas[s2.triangle]));
    const Eigen::Index row = Eigen::Index(rows++);
    for (int k = 0; k < 3; ++k) {
      entries.emplace_back(row, v1[k], root * glm::dot(gradients[s1.triangle][k], m1));
      entries.emplace_back(row, v2[k], root * glm::dot(gradients[s2.triangle][k], m2));
    }
  }
  SparseMatrix D{Eigen::Index(rows), Eigen::Index(nodeCount)};
  D.setFromTriplets(entries.begin(), entries.end());
  entries = {};
  SparseMatrix Q = SparseMatrix(D.transpose()) * D;
  return Q;
}

struct Fit {
  Eigen::MatrixXd values;
  double lambda = 0.0, effectiveDof = 0.0;
  bool smoothed = false;
};

// Solves (W + lambda Q) F = W Y for one lambda, with the influence matrix's trace, tr(W^1/2
// M^-1 W^1/2): exact (one solve per node) for a small region, else from the probes `Z`.
//
// The unknowns are renumbered in nested-dissection order (nested_dissection.h) and factorised in
// that order: at 10^5 nodes a region's factorisations take less time than under Eigen's
// minimum-degree order. The factorisation is Eigen's supernodal LU, its pivots kept on the
// diagonal (the matrix is symmetric positive definite): it works on dense blocks of columns,
// and solves a 1.2e5-node region for one lambda in 1.6 s where the simplicial LDL^T took 2.6 s.
class RegionSolver {
 public:
  explicit RegionSolver(const RegionProblem& problem) {
    const Eigen::Index n = Eigen::Index(problem.nodes.size());
    const std::vector<int> order = nestedDissectionOrder(problem.Q, problem.positions);
    Eigen::VectorXi newIndex(n);  // P: old index -> new
    for (Eigen::Index k = 0; k < n; ++k) newIndex(order[size_t(k)]) = int(k);
    P_ = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>(newIndex);
    Q_ = problem.Q.twistedBy(P_);
    W_ = Eigen::VectorXd(P_ * problem.weights).asDiagonal();
    SparseMatrix M = SparseMatrix(W_) + Q_;
    M.makeCompressed();
    lu_.isSymmetric(true);  // W + lambda Q is: diagonal pivots, no search
    lu_.setPivotThreshold(0.0);
    lu_.analyzePattern(M);
    exactTrace_ = n <= 200;
    const Eigen::Index probes = exactTrace_ ? n : 6;
    Z_ = Eigen::MatrixXd(n, probes);
    if (exactTrace_) {
      Z_.setIdentity();
    } else {
      std::mt19937_64 random(n);  // the same probes for every lambda: a smooth GCV curve
      for (Eigen::Index j = 0; j < probes; ++j)
        for (Eigen::Index i = 0; i < n; ++i) Z_(i, j) = (random() & 1) ? 1.0 : -1.0;
    }
    const Eigen::VectorXd weights = P_ * problem.weights;
    Z_ = weights.cwiseSqrt().asDiagonal() * Z_;  // W^1/2 Z, in the new order
    rhs_ = Eigen::MatrixXd(n, 3 + probes);
    rhs_ << P_ * Eigen::MatrixXd(problem.weights.asDiagonal() * problem.values), Z_;
  }

  // F for one lambda, the influence matrix's trace, and (with `slopes`) their derivatives in
  // lambda: dF = -M^-1 Q F (one more solve, of three columns), d tr = -sum z^T W^1/2 M^-1 Q M^-1
  // W^1/2 z over the probes, from the probes' own solutions.
  struct Solution {
    Eigen::MatrixXd F, dF;
    double trace = 0.0, dTrace = 0.0;
  };

  // Whether the factorisation succeeded and its results are finite.
  bool solve(double lambda, bool slopes, Solution& out) {
    SparseMatrix M = SparseMatrix(W_) + lambda * Q_;
    M.makeCompressed();
    lu_.factorize(M);
    if (lu_.info() != Eigen::Success) return false;
    const Eigen::MatrixXd X = lu_.solve(rhs_);
    out.F = P_.transpose() * Eigen::MatrixXd(X.leftCols(3));
    const Eigen::MatrixXd probed = X.rightCols(rhs_.cols() - 3);
    const double probes = exactTrace_ ? 1.0 : double(probed.cols());
    out.trace = (Z_.cwiseProduct(probed)).sum() / probes;
    if (slopes) {
      const Eigen::MatrixXd QX = Q_ * X;
      out.dF = -(P_.transpose() * Eigen::MatrixXd(lu_.solve(Eigen::MatrixXd(QX.leftCols(3)))));
      out.dTrace = -probed.cwiseProduct(QX.rightCols(probed.cols())).sum() / probes;
    }
    return std::isfinite(out.trace) && out.F.allFinite() && (!slopes || (std::isfinite(out.dTrace) && out.dF.allFinite()));
  }

 private:
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P_;
  SparseMatrix Q_, W_;  // in the new order
  Eigen::SparseLU<SparseMatrix, Eigen::NaturalOrdering<int>> lu_;
  bool exactTrace_ = false;
  Eigen::MatrixXd Z_, rhs_;
};

// Craven & Wahba's GCV score, n RSS_w / (n - gamma tr A)^2 over the three channels, with each
// degree of freedom charged gamma = 1.4 times (Kim & Gu 2004; mgcv's `gamma`): plain GCV (gamma
// 1) now and then takes the data's noise for signal and nearly interpolates a small region.
// The score has a pole where gamma tr A reaches n; below it (less smoothing) there is no score.
constexpr double kGamma = 1.4;
bool pastThePole(const RegionProblem& problem, double trace) {
  return double(problem.nodes.size()) - kGamma * trace <= 0.5;
}
double gcvScore(const RegionProblem& problem, const Eigen::MatrixXd& F, double trace) {
  const double n = double(problem.nodes.size());
  const double residual = (problem.weights.asDiagonal() * (F - problem.values).cwiseAbs2()).sum() / 3.0;
  const double free = n - kGamma * trace;
  return !pastThePole(problem, trace) ? n * residual / (free * free) : std::numeric_limits<double>::infinity();
}

// The sign of GCV's derivative in lambda: +1 where more smoothing scores worse, -1 where better.
// d/dlambda [RSS_w / (n - gamma tr)^2] has the sign of RSS_w' (n - gamma tr) + 2 gamma RSS_w tr'.
int gcvSlopeSign(const RegionProblem& problem, const RegionSolver::Solution& s) {
  const Eigen::MatrixXd residual = s.F - problem.values;
  const double rss = (problem.weights.asDiagonal() * residual.cwiseAbs2()).sum();
  const double rssSlope = 2.0 * (problem.weights.asDiagonal() * residual).cwiseProduct(s.dF).sum();
  const double slope = rssSlope * (double(problem.nodes.size()) - kGamma * s.trace) + 2.0 * kGamma * rss * s.dTrace;
  return slope > 0.0 ? 1 : slope < 0.0 ? -1 : 0;
}

// Whether a fit departs from the values by no more than their standard errors allow: the mean
// over the nodes of (luminance residual / standard error)^2 at most kDiscrepancy. GCV sees only the
// values, and where a small region's values change steeply (a ceiling beside a light) it may
// take the change for noise; the standard errors say it is not.
constexpr double kDiscrepancy = 3.0;
bool withinStandardErrors(const RegionProblem& problem, const Eigen::MatrixXd& F) {
  if (problem.inverseVariance.size() == 0) return true;
  const Eigen::Vector3d luminance(0.2126, 0.7152, 0.0722);
  const Eigen::VectorXd residual = (F - problem.values) * luminance;
  return problem.inverseVariance.dot(residual.cwiseAbs2()) <= kDiscrepancy * double(problem.nodes.size());
}

// Fewer nodes than this and cross-validation cannot tell noise from signal: values kept. With
// standard errors the discrepancy check guards the fit, and 25 are enough; without them
// cross-validation alone judges, and took the kinks of fig. 9.14's 38-node receiver (exact
// values) for noise, doubling the error against the gather.
constexpr size_t kSmallestSmoothedRegion = 25, kSmallestJudgedByValuesAlone = 100;

Fit fitRegion(const RegionProblem& problem, const ThinPlateSettings& settings) {
  Fit fit;
  fit.values = problem.values;
  fit.effectiveDof = double(problem.nodes.size());
  if (problem.bendingEdges == 0 || (settings.lambda && *settings.lambda == 0.0) || !(problem.weights.sum() > 0.0))
    return fit;
  const size_t smallest = problem.inverseVariance.size() > 0 ? kSmallestSmoothedRegion : kSmallestJudgedByValuesAlone;
  if (!settings.lambda && problem.nodes.size() < smallest) return fit;
  RegionSolver solver(problem);
  RegionSolver::Solution solution;
  if (settings.lambda) {
    if (!solver.solve(*settings.lambda, false, solution)) return fit;
    fit = {solution.F, *settings.lambda, solution.trace, true};
    return fit;
  }
  // lambda = scale 10^t, scale where both terms weigh alike. GCV's curve in t has one valley
  // (as a rule): whole decades from t = 1 (the Cornell box's regions find it in 0..2), each
  // step taken the way the score's slope there points down, until the best decade's downhill
  // neighbour has been tried and found worse (or the slope is flat): with one valley, the best
  // decade is then one of the two around its floor, as walking both ways would find. Each t
  // costs a factorisation, so every fit is kept and the best one returned; the valley is flat
  // enough that half decades more changed the Cornell box's errors in the third digit and cost
  // a third more time.
  const double scale = problem.weights.sum() / std::max(problem.Q.diagonal().sum(), 1e-300);
  std::map<double, double> scores;  // by t; infinite where not admissible
  std::map<double, bool> beyondPole;
  std::map<double, int> slopes;  // the sign of the score's derivative
  double bestScore = std::numeric_limits<double>::infinity();
  auto score = [&](double t) {
    const double lambda = scale * std::pow(10.0, t);
    double value = std::numeric_limits<double>::infinity();
    const bool solved = solver.solve(lambda, true, solution);
    beyondPole[t] = solved && pastThePole(problem, solution.trace);
    slopes[t] = solved ? gcvSlopeSign(problem, solution) : 0;
    if (solved && withinStandardErrors(problem, solution.F)) value = gcvScore(problem, solution.F, solution.trace);
    if (value < bestScore) {
      bestScore = value;
      fit = {solution.F, lambda, solution.trace, true};
    }
    scores[t] = value;
  };
  auto bestT = [&] {
    return std::min_element(scores.begin(), scores.end(),
                            [](const auto& a, const auto& b) { return a.second < b.second; })->first;
  };
  constexpr double kLowest = -6.0, kHighest = 6.0;
  score(1.0);
  for (;;) {
    const double t = bestT();
    if (!std::isfinite(scores[t])) {
      // No admissible lambda yet: past the pole, smooth more; else every one tried smooths
      // past the standard errors, smooth less, unless less is past the pole: none is.
      const double highest = scores.rbegin()->first, lowest = scores.begin()->first;
      const double next = beyondPole[highest] ? highest + 1.0 : lowest - 1.0;
      if (next < kLowest || next > kHighest || (next < lowest && beyondPole[lowest])) return fit;
      score(next);
      continue;
    }
    const double next = t - double(slopes[t]);
    if (next == t || scores.count(next) || next < kLowest || next > kHighest) break;
    score(next);
  }
  // The best score next to the pole is the pole's doing, not a valley: GCV found no noise to
  // take off (exact values, as a mesh without standard errors may hold), and any smoothing
  // would only bend the function away from them. The values are kept. The decade below is
  // tried where the walk has not, unless it cannot be past the pole: each eigenvalue's share
  // of the trace, g = 1 / (1 + lambda mu), becomes 10 g / (1 + 9 g) a decade lower, a concave
  // function of g, so the trace there is at most n times that of tr / n (Jensen; also for the
  // probes' estimate, a positive combination of the same g); or unless nothing was smoothed.
  const double t = bestT();
  const double n = double(problem.nodes.size()), share = fit.effectiveDof / n;
  const bool poleCanBeBelow = n * 10.0 * share / (1.0 + 9.0 * share) > (n - 0.5) / kGamma;
  if (!beyondPole.count(t - 1.0) && t - 1.0 >= kLowest && poleCanBeBelow && bestScore > 0.0) score(t - 1.0);
  if (const auto below = beyondPole.find(t - 1.0); below != beyondPole.end() && below->second) {
    fit = Fit{};
    fit.values = problem.values;
    fit.effectiveDof = double(problem.nodes.size());
  }
  return fit;
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
  std::vector<Fit> fits(regions.size());
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
        std::vector<std::array<uint32_t, 3>> triangles;
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
        std::vector<uint64_t> localUntouchable;
        for (uint64_t key : untouchable) {
          const uint32_t a = uint32_t(key >> 32), b = uint32_t(key);
          if (local[a] >= 0 && local[b] >= 0) localUntouchable.push_back(edgeKey(uint32_t(local[a]), uint32_t(local[b])));
        }
        std::sort(localUntouchable.begin(), localUntouchable.end());
        std::vector<Vec3>& positions = problem.positions;
        for (uint32_t node : problem.nodes) positions.push_back(mesh.nodes[node].position);
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
        if (!mesh.materials[first.material].isEmitter())
          problem.Q = bendingEnergy(triangles, localUntouchable, problem.nodes.size(), positions,
                                    problem.bendingEdges);
        fits[r] = fitRegion(problem, settings);
        summary.lambda = fits[r].lambda;
        summary.effectiveDof = fits[r].effectiveDof;
        summary.smoothed = fits[r].smoothed;
        problem.Q = SparseMatrix();  // freed as soon as fitted
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
