#pragma once
// A hash grid of points: "which points lie near here" without comparing all pairs. Cells are
// cubes hashed to 64 bits; two cells sharing a hash only add candidates, which callers test
// by distance anyway. Each cell is a linked list through one array: no allocation per cell.
// The cells live in one open-addressing table (linear probing): a lookup is a few reads of one
// array, where a node-based map chased a pointer per lookup (weldPoints and the T-vertex search
// make millions at 10^6 elements).
#include "core/types.h"

#include <cstdint>
#include <vector>

namespace radview {

class PointGrid {
 public:
  // Cells of edge cellSize (> 0) counted from `origin`, which should be the points' lower
  // corner so that cell indices stay small.
  PointGrid(const Vec3& origin, double cellSize, size_t expectedPoints) : origin_(origin), cellSize_(cellSize) {
    resizeTable(expectedPoints);
    next_.reserve(expectedPoints);
  }

  void insert(uint32_t id, const Vec3& p) {
    if (2 * (cells_ + 1) > heads_.size()) resizeTable(cells_ + 1);
    const uint64_t k = key(cellOf(p));
    size_t slot = slotOf(k);
    while (heads_[slot] != kEnd && keys_[slot] != k) slot = (slot + 1) & mask_;
    if (heads_[slot] == kEnd) {
      keys_[slot] = k;
      ++cells_;
    }
    if (id >= next_.size()) next_.resize(id + 1, kEnd);
    next_[id] = heads_[slot];
    heads_[slot] = id;
  }

  // Calls f(id) for every point inserted in a cell that overlaps the box [lo, hi].
  template <typename F>
  void forEachNear(const Vec3& lo, const Vec3& hi, F f) const {
    const glm::i64vec3 a = cellOf(lo), b = cellOf(hi);
    for (int64_t x = a.x; x <= b.x; ++x)
      for (int64_t y = a.y; y <= b.y; ++y)
        for (int64_t z = a.z; z <= b.z; ++z) {
          const uint64_t k = key({x, y, z});
          for (size_t slot = slotOf(k); heads_[slot] != kEnd; slot = (slot + 1) & mask_)
            if (keys_[slot] == k) {
              for (uint32_t id = heads_[slot]; id != kEnd; id = next_[id]) f(id);
              break;
            }
        }
  }

 private:
  static constexpr uint32_t kEnd = UINT32_MAX;
  Vec3 origin_;
  double cellSize_;
  std::vector<uint64_t> keys_;   // per slot: the hashed cell
  std::vector<uint32_t> heads_;  // per slot: the last point inserted in it, kEnd for an empty slot
  size_t mask_ = 0, cells_ = 0;
  int shift_ = 64;
  std::vector<uint32_t> next_;  // per point: the previous one in its cell

  glm::i64vec3 cellOf(const Vec3& p) const { return glm::i64vec3(glm::floor((p - origin_) / cellSize_)); }
  static uint64_t key(const glm::i64vec3& c) {
    return uint64_t(c.x) * 0x9E3779B97F4A7C15ull ^ uint64_t(c.y) * 0xC2B2AE3D27D4EB4Full ^
           uint64_t(c.z) * 0x165667B19E3779F9ull;
  }
  // The key's home slot: its high bits after one more multiplication (Fibonacci hashing).
  size_t slotOf(uint64_t k) const { return size_t((k * 0x9E3779B97F4A7C15ull) >> shift_) & mask_; }
  // At least twice `cells` slots, a power of two, the cells placed again.
  void resizeTable(size_t cells) {
    size_t capacity = 16;
    int bits = 4;
    while (capacity < 2 * cells) capacity *= 2, ++bits;
    std::vector<uint64_t> keys(capacity, 0);
    std::vector<uint32_t> heads(capacity, kEnd);
    keys_.swap(keys);
    heads_.swap(heads);
    mask_ = capacity - 1;
    shift_ = 64 - bits;
    for (size_t old = 0; old < heads.size(); ++old)
      if (heads[old] != kEnd) {
        size_t slot = slotOf(keys[old]);
        while (heads_[slot] != kEnd) slot = (slot + 1) & mask_;
        keys_[slot] = keys[old];
        heads_[slot] = heads[old];
      }
  }
};

}  // namespace radview
