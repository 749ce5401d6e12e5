#include "geom/weld.h"

#include "geom/point_grid.h"

#include <algorithm>
#include <array>
#include <map>

namespace radview {

namespace {

WeldedPoints weldIdentical(const std::vector<Vec3>& points) {
  WeldedPoints out;
  std::map<std::array<double, 3>, uint32_t> ids;
  for (const Vec3& p : points) {
    auto [it, added] = ids.emplace(std::array<double, 3>{p.x, p.y, p.z}, out.count());
    if (added) out.position.push_back(p);
    out.id.push_back(it->second);
  }
  return out;
}

}  // namespace

WeldedPoints weldPoints(const std::vector<Vec3>& points, double distance) {
  if (!(distance > 0.0)) return weldIdentical(points);
  Bounds bounds;
  for (const Vec3& p : points) bounds.extend(p);
  // Below double rounding of the extent a distance means "identical" anyway; the floor keeps
  // the cell indices within 64 bits.
  distance = std::max(distance, 1e-15 * bounds.diagonal());
  // Cells 16 times the distance: the box of half-width `distance` about a point meets one of
  // them in most cases (2 x 2 x 2 at most), and a cell holds more than one group only where
  // points lie within a few weld distances of each other. The cells start off the lattice a
  // regular mesh's nodes lie on, so that those are not on cell faces. Any cells find the same
  // groups.
  const double cell = 16.0 * distance;
  PointGrid groupStarts(bounds.lo - Vec3(0.377 * cell), cell, points.size());
  WeldedPoints out;
  out.id.reserve(points.size());
  const double distance2 = distance * distance;
  for (const Vec3& p : points) {
    uint32_t found = UINT32_MAX;
    groupStarts.forEachNear(p - distance, p + distance, [&](uint32_t group) {
      const Vec3 d = out.position[group] - p;
      if (group < found && glm::dot(d, d) <= distance2) found = group;
    });
    if (found == UINT32_MAX) {
      found = out.count();
      out.position.push_back(p);
      groupStarts.insert(found, p);
    }
    out.id.push_back(found);
  }
  return out;
}

}  // namespace radview
