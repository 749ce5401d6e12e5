#pragma once
// An elimination order for a sparse symmetric matrix whose unknowns sit at points of a surface
// mesh: nested dissection (George 1973) by coordinate bisection. The points are split at the
// median of their widest coordinate; the nodes of one half coupled to the other (the separator)
// go last, each half is ordered the same way, down to small pieces. On a planar mesh the
// separators are about sqrt(n) nodes, so a sparse Cholesky factor fills far less than under a
// minimum-degree order once regions reach 10^5 nodes (the thin-plate spline's, thin_plate.h).
#include "core/types.h"

#include <Eigen/SparseCore>

#include <vector>

namespace radview {

// order[k] is the index of the unknown eliminated k-th. `coupling`'s pattern says which unknowns
// are coupled (symmetric, both triangles stored); positions[i] is unknown i's point.
std::vector<int> nestedDissectionOrder(const Eigen::SparseMatrix<double>& coupling, const std::vector<Vec3>& positions);

}  // namespace radview
