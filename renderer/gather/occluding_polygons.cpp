#include "gather/occluding_polygons.h"

#include "core/error.h"
#include "geom/polygon.h"
#include "trace/form_factor.h"

#include <algorithm>
#include <cmath>

namespace radview {

namespace {

using Fragment = std::vector<Vec3>;

double areaOf(const Fragment& f) { return f.size() < 3 ? 0.0 : area(f); }

}  // namespace

OccludingPolygons::OccludingPolygons(const std::vector<std::vector<Vec3>>& polygons) {
  RADVIEW_CHECK(polygons.size() <= kMaxPolygons);
  for (const std::vector<Vec3>& corners : polygons) {
    RADVIEW_CHECK(corners.size() <= kMaxCorners);
    Polygon p{corners, {}, unitNormal(corners), centroid(corners), 0.0, 0};
    RADVIEW_CHECK(corners.size() >= 3 && p.normal != Vec3(0.0));
    Bounds bounds;
    for (size_t k = 0; k < corners.size(); ++k) {
      bounds.extend(corners[k]);
      p.edgeInwards.push_back(glm::cross(p.normal, corners[(k + 1) % corners.size()] - corners[k]));
    }
    p.size = bounds.diagonal();
    polygons_.push_back(std::move(p));
  }
  // Whether polygon a passes through b's interior: a has corners on both sides of b's plane,
  // and the segment where a meets that plane runs through b (not only along its boundary).
  auto pierces = [](const Polygon& a, const Polygon& b) {
    const double tolerance = 1e-9 * std::max(a.size, b.size);
    std::vector<double> d;
    bool below = false, above = false;
    for (const Vec3& v : a.corners) {
      d.push_back(glm::dot(v - b.centre, b.normal));
      below |= d.back() < -tolerance;
      above |= d.back() > tolerance;
    }
    if (!below || !above) return false;
    std::vector<Vec3> ends;
    for (size_t k = 0; k < a.corners.size(); ++k) {
      const size_t next = (k + 1) % a.corners.size();
      if ((d[k] < 0.0) != (d[next] < 0.0))
        ends.push_back(a.corners[k] + (d[k] / (d[k] - d[next])) * (a.corners[next] - a.corners[k]));
    }
    if (ends.size() < 2) return false;
    // The segment clipped to b, with the edges moved inwards by the tolerance.
    double t0 = 0.0, t1 = 1.0;
    for (size_t k = 0; k < b.corners.size() && t0 < t1; ++k) {
      const Vec3 inwards = glm::normalize(b.edgeInwards[k]);
      const double g0 = glm::dot(ends[0] - b.corners[k], inwards) - tolerance;
      const double g1 = glm::dot(ends[1] - b.corners[k], inwards) - tolerance;
      if (g0 < 0.0 && g1 < 0.0) return false;
      if (g0 < 0.0) t0 = std::max(t0, g0 / (g0 - g1));
      if (g1 < 0.0) t1 = std::min(t1, g0 / (g0 - g1));
    }
    return (t1 - t0) * glm::length(ends[1] - ends[0]) > tolerance;
  };
  auto hasCornerBehind = [](const Polygon& a, const Polygon& b) {
    const double tolerance = 1e-9 * std::max(a.size, b.size);
    return std::any_of(a.corners.begin(), a.corners.end(),
                       [&](const Vec3& v) { return glm::dot(v - b.centre, b.normal) < -tolerance; });
  };
  for (size_t i = 0; i < polygons_.size(); ++i)
    for (size_t k = i + 1; k < polygons_.size(); ++k) {
      const Polygon &a = polygons_[i], &b = polygons_[k];
      const bool coplanar = std::abs(glm::dot(a.normal, b.normal)) > 1.0 - 1e-12 &&
                            std::abs(glm::dot(b.centre - a.centre, a.normal)) < 1e-9 * std::max(a.size, b.size);
      if (coplanar || pierces(a, b) || pierces(b, a)) continue;
      // To hide a point of one from x, the other must cross the segment between them: the
      // point lies behind the other's plane, as seen from x in front of it.
      if (hasCornerBehind(a, b)) polygons_[i].hiddenBy |= uint64_t(1) << k;
      if (hasCornerBehind(b, a)) polygons_[k].hiddenBy |= uint64_t(1) << i;
    }
}

uint64_t OccludingPolygons::facing(const Vec3& x) const {
  uint64_t mask = 0;
  for (size_t i = 0; i < polygons_.size(); ++i)
    if (glm::dot(x - polygons_[i].centre, polygons_[i].normal) > 1e-12 * polygons_[i].size) mask |= uint64_t(1) << i;
  return mask;
}

double OccludingPolygons::crossing(const Polygon& p, const Vec3& x, const Vec3& direction) const {
  const double approach = -glm::dot(direction, p.normal);
  if (!(approach > 0.0)) return -1.0;
  const double t = glm::dot(x - p.centre, p.normal) / approach;
  const Vec3 q = x + t * direction;
  for (size_t k = 0; k < p.corners.size(); ++k)
    if (glm::dot(q - p.corners[k], p.edgeInwards[k]) < 0.0) return -1.0;
  return t;
}

uint64_t OccludingPolygons::seenAlong(const Vec3& x, const Vec3& direction, uint64_t facing) const {
  double t[kMaxPolygons];
  uint64_t crossed = 0;
  for (uint64_t m = facing; m != 0; m &= m - 1) {
    const size_t i = size_t(__builtin_ctzll(m));
    t[i] = crossing(polygons_[i], x, direction);
    if (t[i] >= 0.0) crossed |= uint64_t(1) << i;
  }
  uint64_t seen = 0;
  for (uint64_t m = crossed; m != 0; m &= m - 1) {
    const size_t i = size_t(__builtin_ctzll(m));
    bool hidden = false;
    for (uint64_t h = crossed & polygons_[i].hiddenBy; h != 0 && !hidden; h &= h - 1)
      hidden = t[size_t(__builtin_ctzll(h))] < t[i];
    if (!hidden) seen |= uint64_t(1) << i;
  }
  return seen;
}

bool OccludingPolygons::seenAt(const Vec3& x, const Vec3& target, uint64_t facing, size_t i) const {
  const Vec3 direction = glm::normalize(target - x);
  const double ti = crossing(polygons_[i], x, direction);
  if (ti < 0.0) return false;
  for (uint64_t h = facing & polygons_[i].hiddenBy; h != 0; h &= h - 1) {
    const double tk = crossing(polygons_[size_t(__builtin_ctzll(h))], x, direction);
    if (tk >= 0.0 && tk < ti) return false;
  }
  return true;
}

size_t OccludingPolygons::visiblePieces(size_t i, const Vec3& x, const Vec3& n, uint64_t facing,
                                        std::vector<Fragment>& fragments, std::vector<Fragment>& next) const {
  // fragments[0 .. count) are the pieces so far; next[0 .. nextCount) those after one more
  // polygon's cone is taken out. Entries past the counts keep their storage for reuse.
  auto slot = [](std::vector<Fragment>& list, size_t at) -> Fragment& {
    if (list.size() <= at) list.resize(at + 1);
    return list[at];
  };
  thread_local Fragment inside, rest, scratch;
  const Polygon& p = polygons_[i];
  const double tiny = 1e-12 * area(p.corners);
  clipToHalfSpace(p.corners, x, n, slot(fragments, 0));
  size_t count = areaOf(fragments[0]) > tiny ? 1 : 0;
  for (uint64_t h = facing & p.hiddenBy; h != 0 && count > 0; h &= h - 1) {
    const Polygon& k = polygons_[size_t(__builtin_ctzll(h))];
    // The sides of the cone from x through k, each normal pointing into the cone.
    Vec3 sides[kMaxCorners];
    const size_t sideCount = std::min(k.corners.size(), kMaxCorners);
    for (size_t e = 0; e < sideCount; ++e) {
      Vec3 side = glm::cross(k.corners[e] - x, k.corners[(e + 1) % k.corners.size()] - x);
      if (glm::dot(side, k.centre - x) < 0.0) side = -side;
      sides[e] = side;
    }
    size_t nextCount = 0;
    for (size_t f = 0; f < count; ++f) {
      Fragment& fragment = fragments[f];
      // Most fragments lie wholly outside one side of the cone: nothing to clip.
      const bool apart = std::any_of(sides, sides + sideCount, [&](const Vec3& side) {
        return std::all_of(fragment.begin(), fragment.end(),
                           [&](const Vec3& v) { return glm::dot(side, v - x) <= 0.0; });
      });
      bool inFront = false;
      if (!apart) {
        inside = fragment;
        for (size_t e = 0; e < sideCount; ++e) {
          clipToHalfSpace(inside, x, sides[e], scratch);
          std::swap(inside, scratch);
        }
        if (areaOf(inside) > tiny) {
          // k is in front of the fragment across the whole of their overlap (the two do not
          // cross): test the ray through the overlap's centroid, which meets p at t = 1.
          const Vec3 ray = centroid(inside) - x;
          const double approach = -glm::dot(ray, k.normal);
          inFront = approach > 0.0 && glm::dot(x - k.centre, k.normal) / approach < 1.0;
        }
      }
      if (!inFront) {
        std::swap(slot(next, nextCount++), fragment);
        continue;
      }
      // The fragment less the cone: the part outside each side and inside the ones before.
      std::swap(rest, fragment);
      for (size_t e = 0; e < sideCount; ++e) {
        Fragment& outside = slot(next, nextCount);
        clipToHalfSpace(rest, x, -sides[e], outside);
        if (areaOf(outside) > tiny) ++nextCount;
        clipToHalfSpace(rest, x, sides[e], scratch);
        std::swap(rest, scratch);
        if (!(areaOf(rest) > tiny)) break;
      }
    }
    std::swap(fragments, next);
    count = nextCount;
  }
  return count;
}

}  // namespace radview
