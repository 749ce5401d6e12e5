#include "interp/nested_dissection.h"

#include <algorithm>

namespace radview {

namespace {

constexpr size_t kSmallestPiece = 64;  // ordered as they come: too small to gain from splitting

struct Dissection {
  const Eigen::SparseMatrix<double>& coupling;
  const std::vector<Vec3>& positions;
  std::vector<int> order;
  std::vector<int> owner;  // the call that last split the unknown
  std::vector<char> half;  // its side in that split
  int calls = 0;

  void dissect(std::vector<int> piece) {
    if (piece.size() <= kSmallestPiece) {
      order.insert(order.end(), piece.begin(), piece.end());
      return;
    }
    Vec3 lo(positions[size_t(piece[0])]), hi(lo);
    for (int i : piece) lo = glm::min(lo, positions[size_t(i)]), hi = glm::max(hi, positions[size_t(i)]);
    const Vec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const auto middle = piece.begin() + ptrdiff_t(piece.size() / 2);
    std::nth_element(piece.begin(), middle, piece.end(),
                     [&](int a, int b) { return positions[size_t(a)][axis] < positions[size_t(b)][axis]; });
    const int call = ++calls;
    for (auto it = piece.begin(); it != piece.end(); ++it) {
      owner[size_t(*it)] = call;
      half[size_t(*it)] = it < middle ? 0 : 1;
    }
    std::vector<int> left, right, separator;
    for (auto it = piece.begin(); it != piece.end(); ++it) {
      if (it >= middle) {
        right.push_back(*it);
        continue;
      }
      bool coupled = false;
      for (Eigen::SparseMatrix<double>::InnerIterator j(coupling, *it); j && !coupled; ++j)
        coupled = owner[size_t(j.index())] == call && half[size_t(j.index())] == 1;
      (coupled ? separator : left).push_back(*it);
    }
    if (left.empty() || right.empty()) {  // nothing to split (coincident points): keep as is
      order.insert(order.end(), piece.begin(), piece.end());
      return;
    }
    dissect(std::move(left));
    dissect(std::move(right));
    order.insert(order.end(), separator.begin(), separator.end());
  }
};

}  // namespace

std::vector<int> nestedDissectionOrder(const Eigen::SparseMatrix<double>& coupling, const std::vector<Vec3>& positions) {
  const size_t n = positions.size();
  Dissection d{coupling, positions, {}, std::vector<int>(n, 0), std::vector<char>(n, 0), 0};
  d.order.reserve(n);
  std::vector<int> all(n);
  for (size_t i = 0; i < n; ++i) all[i] = int(i);
  d.dissect(std::move(all));
  return d.order;
}

}  // namespace radview
