#pragma once
// Disjoint sets of the indices 0..n-1 (union-find, with path halving): which triangle corners
// share a gradient sector, which corners of a fan or a node stay joined after an edge is cut.
// `Index` is the narrowest type that holds n (uint32_t for corners at 10^6 elements).
#include <cstddef>
#include <numeric>
#include <vector>

namespace radview {

template <typename Index = size_t>
class DisjointSets {
 public:
  explicit DisjointSets(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), Index(0)); }
  // The representative of x's set: the same for every member, until a join.
  Index find(Index x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void join(Index a, Index b) { parent_[find(a)] = find(b); }

 private:
  std::vector<Index> parent_;
};

}  // namespace radview
