#pragma once
// One region's thin-plate smoothing spline (thin_plate.h): its bending energy, the sparse
// systems (W + lambda Q) f = W B, and lambda by generalised cross-validation. A region too large
// to cross-validate whole in good time is cross-validated in pieces.
#include "core/types.h"
#include "interp/thin_plate.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <array>
#include <cstdint>
#include <vector>

namespace radview {

inline uint64_t edgeKey(uint32_t a, uint32_t b) { return uint64_t(std::min(a, b)) << 32 | std::max(a, b); }

// One region's fitting problem over its local node indices.
struct RegionProblem {
  std::vector<uint32_t> nodes;  // the mesh's
  std::vector<Vec3> positions;  // the nodes'
  Eigen::MatrixXd values;       // nodes x 3
  Eigen::VectorXd weights;
  // With standard errors: 1 / (SE^2 + s0^2) of the luminance, not rescaled (the discrepancy
  // check's yardstick); empty without them.
  Eigen::VectorXd inverseVariance;
  // The region's conforming triangles, and the edges without bending energy (edgeKey, sorted).
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint64_t> untouchable;
  // Q, the bending energy's matrix (E(f) = f^T Q f), and the count of edges it bends across;
  // empty for an emitter (values kept).
  Eigen::SparseMatrix<double> Q;
  size_t bendingEdges = 0;
};

// Sets problem.Q and problem.bendingEdges from its triangles: the normal-derivative jumps across
// the interior edges (thin_plate.h).
void setBendingEnergy(RegionProblem& problem);

struct RegionFit {
  Eigen::MatrixXd values;  // nodes x 3
  double lambda = 0.0, effectiveDof = 0.0;
  bool smoothed = false;  // false: the values kept
};

RegionFit fitRegion(const RegionProblem& problem, const ThinPlateSettings& settings);

}  // namespace radview
