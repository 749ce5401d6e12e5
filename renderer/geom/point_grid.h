#pragma once
// A hash grid of points: "which points lie near here" without comparing all pairs. Cells are
// cubes hashed to 64 bits; two cells sharing a hash only add candidates, which callers test
// by distance anyway. Each cell is a linked list through one array: no allocation per cell.
#include "core/types.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace radview {

class PointGrid {
 public:
  // Cells of edge cellSize (> 0) counted from `origin`, which should be the points' lower
  // corner so that cell indices stay small.
  PointGrid(const Vec3& origin, double cellSize, size_t expectedPoints)
      : origin_(origin), cellSize_(cellSize) {
    headOfCell_.reserve(expectedPoints);
    next_.reserve(expectedPoints);
  }

  void insert(uint32_t id, const Vec3& p) {
    auto [it, added] = headOfCell_.emplace(key(cellOf(p)), id);
    if (id >= next_.size()) next_.resize(id + 1, kEnd);
    next_[id] = added ? kEnd : it->second;
    it->second = id;
  }

  // Calls f(id) for every point inserted in a cell that overlaps the box [lo, hi].
  template <typename F>
  void forEachNear(const Vec3& lo, const Vec3& hi, F f) const {
    const glm::i64vec3 a = cellOf(lo), b = cellOf(hi);
    for (int64_t x = a.x; x <= b.x; ++x)
      for (int64_t y = a.y; y <= b.y; ++y)
        for (int64_t z = a.z; z <= b.z; ++z) {
          auto it = headOfCell_.find(key({x, y, z}));
          if (it == headOfCell_.end()) continue;
          for (uint32_t id = it->second; id != kEnd; id = next_[id]) f(id);
        }
  }

 private:
  static constexpr uint32_t kEnd = UINT32_MAX;
  Vec3 origin_;
  double cellSize_;
  std::unordered_map<uint64_t, uint32_t> headOfCell_;  // hashed cell -> last point inserted
  std::vector<uint32_t> next_;                         // per point: the previous one in its cell

  glm::i64vec3 cellOf(const Vec3& p) const { return glm::i64vec3(glm::floor((p - origin_) / cellSize_)); }
  static uint64_t key(const glm::i64vec3& c) {
    return uint64_t(c.x) * 0x9E3779B97F4A7C15ull ^ uint64_t(c.y) * 0xC2B2AE3D27D4EB4Full ^
           uint64_t(c.z) * 0x165667B19E3779F9ull;
  }
};

}  // namespace radview
