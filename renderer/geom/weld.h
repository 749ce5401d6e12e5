#pragma once
// Welding: grouping points that lie within a distance of each other, without comparing all
// pairs (a hash grid with cells twice the distance).
#include "core/types.h"

#include <cstdint>
#include <vector>

namespace radview {

struct WeldedPoints {
  std::vector<uint32_t> id;    // per input point: its group, 0 .. count-1, in order of first point
  std::vector<Vec3> position;  // per group: the position of its first point
  uint32_t count() const { return static_cast<uint32_t>(position.size()); }
};

// Each point joins the group of the first earlier point within `distance` of it that started a
// group, or starts a new group. Deterministic for a given input order. distance <= 0 welds
// only identical points. Points must be finite.
WeldedPoints weldPoints(const std::vector<Vec3>& points, double distance);

}  // namespace radview
