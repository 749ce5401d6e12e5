// The nested-dissection order (interp/nested_dissection.h): a permutation, whose factor fills
// less than the natural order's on a grid, and the same solution as any other order.
#include "interp/nested_dissection.h"

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace radview {
namespace {

// The 13-point biharmonic stencil's pattern on an n x n grid (the thin-plate energy couples a
// node to its neighbours' neighbours), diagonally dominant.
Eigen::SparseMatrix<double> gridMatrix(int n, std::vector<Vec3>& positions) {
  std::vector<Eigen::Triplet<double>> entries;
  auto id = [n](int i, int j) { return j * n + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      positions.push_back(Vec3(i, j, 0));
      for (int dj = -2; dj <= 2; ++dj)
        for (int di = -2; di <= 2; ++di) {
          if (std::abs(di) + std::abs(dj) > 2 || i + di < 0 || i + di >= n || j + dj < 0 || j + dj >= n) continue;
          entries.emplace_back(id(i, j), id(i + di, j + dj), di == 0 && dj == 0 ? 20.0 : -1.0);
        }
    }
  Eigen::SparseMatrix<double> A(n * n, n * n);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

template <typename Solver>
Eigen::Index factorNonZeros(const Eigen::SparseMatrix<double>& A, Solver& solver) {
  solver.compute(A);
  EXPECT_EQ(solver.info(), Eigen::Success);
  return Eigen::SparseMatrix<double>(solver.matrixL()).nonZeros();
}

TEST(NestedDissection, APermutationThatFillsLessAndSolvesTheSame) {
  std::vector<Vec3> positions;
  const Eigen::SparseMatrix<double> A = gridMatrix(60, positions);
  const std::vector<int> order = nestedDissectionOrder(A, positions);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> identity(order.size());
  std::iota(identity.begin(), identity.end(), 0);
  ASSERT_EQ(sorted, identity);

  Eigen::VectorXi newIndex(Eigen::Index(order.size()));
  for (size_t k = 0; k < order.size(); ++k) newIndex(order[k]) = int(k);
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(newIndex);
  Eigen::SparseMatrix<double> permuted;
  permuted = A.twistedBy(P);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> dissected, natural;
  const Eigen::Index filledDissected = factorNonZeros(permuted, dissected), filledNatural = factorNonZeros(A, natural);
  EXPECT_LT(filledDissected, filledNatural) << "nested dissection " << filledDissected << ", natural " << filledNatural;

  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 1.0);
  const Eigen::VectorXd x = P.transpose() * dissected.solve(P * b);
  EXPECT_LT((A * x - b).norm(), 1e-10 * b.norm());
}

}  // namespace
}  // namespace radview
