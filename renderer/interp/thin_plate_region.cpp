#include "interp/thin_plate_region.h"

#include "interp/nested_dissection.h"

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>

namespace radview {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

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

// Values kept, as where cross-validation cannot tell noise from signal.
RegionFit valuesKept(const RegionProblem& problem) {
  RegionFit fit;
  fit.values = problem.values;
  fit.effectiveDof = double(problem.nodes.size());
  return fit;
}

// lambda by GCV over the whole region: one factorisation per decade tried. The walk starts at
// decade `start` and leaves there the best one found.
RegionFit crossValidate(const RegionProblem& problem, double& start) {
  RegionFit fit = valuesKept(problem);
  RegionSolver solver(problem);
  RegionSolver::Solution solution;
  // lambda = scale 10^t, scale where both terms weigh alike. GCV's curve in t has one valley
  // (as a rule): whole decades from `start` (t = 1 for a region: the Cornell box's regions find
  // it in 0..2), each step taken the way the score's slope there points down, until the best
  // decade's downhill neighbour has been tried and found worse (or the slope is flat): with one
  // valley, the best decade is then one of the two around its floor, as walking both ways
  // would find. Each t costs a factorisation, so every fit is kept and the best one returned;
  // the valley is flat enough that half decades more changed the Cornell box's errors in the
  // third digit and cost a third more time.
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
  score(start);
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
  start = bestT();
  if (const auto below = beyondPole.find(t - 1.0); below != beyondPole.end() && below->second) {
    fit = valuesKept(problem);
  }
  return fit;
}

// Regions above kLargestValidatedWhole nodes are cross-validated in pieces of at most
// kPieceNodes: a factorisation grows faster than its region (1.2e5 nodes 1.6 s, 1.5e4 nodes
// 0.05 s), and GCV's valley lies up to six decades from where the walk starts.
constexpr size_t kLargestValidatedWhole = 12000, kPieceNodes = 8000;

// The region's local node indices split by coordinate bisection (the bounding box's longest
// side, at the median) until no piece holds more than kPieceNodes.
std::vector<std::vector<uint32_t>> splitIntoPieces(const std::vector<Vec3>& positions) {
  std::vector<std::vector<uint32_t>> pieces, todo(1);
  todo[0].resize(positions.size());
  std::iota(todo[0].begin(), todo[0].end(), 0u);
  while (!todo.empty()) {
    std::vector<uint32_t> piece = std::move(todo.back());
    todo.pop_back();
    if (piece.size() <= kPieceNodes) {
      pieces.push_back(std::move(piece));
      continue;
    }
    Vec3 lo(positions[piece[0]]), hi(lo);
    for (uint32_t i : piece) lo = glm::min(lo, positions[i]), hi = glm::max(hi, positions[i]);
    const Vec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const auto middle = piece.begin() + ptrdiff_t(piece.size() / 2);
    std::nth_element(piece.begin(), middle, piece.end(),
                     [&](uint32_t a, uint32_t b) { return positions[a][axis] < positions[b][axis]; });
    todo.emplace_back(piece.begin(), middle);
    todo.emplace_back(middle, piece.end());
  }
  return pieces;
}

// A piece's own problem: its nodes, and the region's triangles with every corner among them
// (the cut is a boundary of the piece: natural boundary conditions there, as at the region's).
RegionProblem pieceProblem(const RegionProblem& region, const std::vector<uint32_t>& piece) {
  RegionProblem p;
  std::vector<int32_t> local(region.nodes.size(), -1);
  const Eigen::Index n = Eigen::Index(piece.size());
  p.values = Eigen::MatrixXd(n, 3);
  p.weights = Eigen::VectorXd(n);
  if (region.inverseVariance.size() > 0) p.inverseVariance = Eigen::VectorXd(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const uint32_t i = piece[size_t(k)];
    local[i] = int32_t(k);
    p.nodes.push_back(region.nodes[i]);
    p.positions.push_back(region.positions[i]);
    p.values.row(k) = region.values.row(i);
    p.weights(k) = region.weights(i);
    if (region.inverseVariance.size() > 0) p.inverseVariance(k) = region.inverseVariance(i);
  }
  for (const auto& t : region.triangles)
    if (local[t[0]] >= 0 && local[t[1]] >= 0 && local[t[2]] >= 0)
      p.triangles.push_back({uint32_t(local[t[0]]), uint32_t(local[t[1]]), uint32_t(local[t[2]])});
  for (uint64_t key : region.untouchable) {
    const int32_t a = local[key >> 32], b = local[uint32_t(key)];
    if (a >= 0 && b >= 0) p.untouchable.push_back(edgeKey(uint32_t(a), uint32_t(b)));
  }
  std::sort(p.untouchable.begin(), p.untouchable.end());
  p.Q = bendingEnergy(p.triangles, p.untouchable, p.nodes.size(), p.positions, p.bendingEdges);
  return p;
}

// lambda for a region too large to cross-validate whole: GCV in each of its pieces, and the
// region fitted once, at the median of the pieces' lambdas (each piece weighing as its nodes).
// The data term and the energy both add up over area, so a lambda that suits a piece suits a
// region of the same mesh, noise and light. Where pieces holding most of the nodes keep their
// values (no noise found), the region keeps its own. With standard errors, a lambda whose
// residuals exceed them is refused here too, a decade less tried instead, twice at most.
RegionFit crossValidateInPieces(const RegionProblem& problem) {
  std::vector<std::pair<double, size_t>> lambdas;  // (log10 lambda, nodes)
  size_t kept = 0, smoothed = 0;
  const size_t smallest = problem.inverseVariance.size() > 0 ? kSmallestSmoothedRegion : kSmallestJudgedByValuesAlone;
  double start = 1.0;  // each piece's walk from where the last one's ended: most take two steps
  for (const std::vector<uint32_t>& piece : splitIntoPieces(problem.positions)) {
    const RegionProblem p = pieceProblem(problem, piece);
    const RegionFit fit = p.bendingEdges == 0 || p.nodes.size() < smallest ? valuesKept(p) : crossValidate(p, start);
    if (fit.smoothed) {
      lambdas.push_back({std::log10(fit.lambda), piece.size()});
      smoothed += piece.size();
    } else {
      kept += piece.size();
    }
  }
  if (kept >= smoothed) return valuesKept(problem);
  std::sort(lambdas.begin(), lambdas.end());
  double lambda = 0.0;
  size_t below = 0;
  for (const auto& [logLambda, nodes] : lambdas)
    if ((below += nodes) * 2 >= smoothed) {
      lambda = std::pow(10.0, logLambda);
      break;
    }
  RegionSolver solver(problem);
  RegionSolver::Solution solution;
  for (int attempt = 0; attempt < 3; ++attempt, lambda /= 10.0) {
    if (!solver.solve(lambda, false, solution)) break;
    if (withinStandardErrors(problem, solution.F)) return {solution.F, lambda, solution.trace, true};
  }
  return valuesKept(problem);
}
}  // namespace

void setBendingEnergy(RegionProblem& problem) {
  problem.Q = bendingEnergy(problem.triangles, problem.untouchable, problem.nodes.size(), problem.positions,
                            problem.bendingEdges);
}

RegionFit fitRegion(const RegionProblem& problem, const ThinPlateSettings& settings) {
  if (problem.bendingEdges == 0 || (settings.lambda && *settings.lambda == 0.0) || !(problem.weights.sum() > 0.0))
    return valuesKept(problem);
  if (settings.lambda) {
    RegionSolver solver(problem);
    RegionSolver::Solution solution;
    if (!solver.solve(*settings.lambda, false, solution)) return valuesKept(problem);
    return {solution.F, *settings.lambda, solution.trace, true};
  }
  const size_t smallest = problem.inverseVariance.size() > 0 ? kSmallestSmoothedRegion : kSmallestJudgedByValuesAlone;
  if (problem.nodes.size() < smallest) return valuesKept(problem);
  if (problem.nodes.size() > kLargestValidatedWhole) return crossValidateInPieces(problem);
  double start = 1.0;
  return crossValidate(problem, start);
}

}  // namespace radview
