#include "gather/control_variates.h"

#include "gather/hemisphere_sampling.h"
#include "geom/convex_hull_cgal.h"
#include "geom/polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace radview {

namespace {

double meanOf(const Rgb& c) { return (c.r + c.g + c.b) / 3.0; }

// Cells of the grids over the planes' hulls, all planes together: each costs a Lambert sum per
// point gathered; more than this reduced the Cornell box's noise no further.
constexpr int kCellBudget = 64;

// One element's part in its plane's radiosity.
struct Facet {
  Vec3 normal{0.0}, centre{0.0};
  double area = 0.0;
  Rgb reflected{0.0};  // the mean of B - E over its corner nodes
  Rgb E{0.0};
};

// Elements grown into one plane.
struct Plane {
  std::vector<uint32_t> elements;
  Vec3 normalTimesArea{0.0};
  Rgb reflectedTimesArea{0.0};
  double area = 0.0;
  Rgb E{0.0};
};

// Planes grown from a seed element across shared nodes to elements within 1 degree of its
// normal, 1e-3 of the mesh's size of its plane and with its emission: a wall whose published
// corners are not quite coplanar is one plane, two faces of a block are two, a lamp in the
// ceiling is a plane of its own.
std::vector<Plane> growPlanes(const RadiosityMesh& mesh, const std::vector<Facet>& facets, double meshSize) {
  constexpr double kCosTolerance = 0.99985;
  const size_t count = mesh.elements.size();
  std::vector<uint32_t> firstOfNode(mesh.nodes.size() + 1, 0), elementsOfNode;
  for (const Element& element : mesh.elements)
    for (uint32_t node : element.corners) ++firstOfNode[node + 1];
  for (size_t n = 0; n < mesh.nodes.size(); ++n) firstOfNode[n + 1] += firstOfNode[n];
  elementsOfNode.resize(firstOfNode.back());
  std::vector<uint32_t> next(firstOfNode.begin(), firstOfNode.end() - 1);
  for (size_t e = 0; e < count; ++e)
    for (uint32_t node : mesh.elements[e].corners) elementsOfNode[next[node]++] = uint32_t(e);

  std::vector<Plane> planes;
  std::vector<uint8_t> taken(count, 0);
  std::vector<uint32_t> stack;
  for (size_t seed = 0; seed < count; ++seed) {
    if (taken[seed] || !(facets[seed].area > 0.0)) continue;
    const Facet& s = facets[seed];
    Plane plane;
    plane.E = s.E;
    stack.assign(1, uint32_t(seed));
    taken[seed] = 1;
    while (!stack.empty()) {
      const uint32_t e = stack.back();
      stack.pop_back();
      plane.elements.push_back(e);
      plane.normalTimesArea += facets[e].area * facets[e].normal;
      plane.reflectedTimesArea += facets[e].area * facets[e].reflected;
      plane.area += facets[e].area;
      for (uint32_t node : mesh.elements[e].corners)
        for (uint32_t i = firstOfNode[node]; i < firstOfNode[node + 1]; ++i) {
          const uint32_t f = elementsOfNode[i];
          if (taken[f] || !(facets[f].area > 0.0) || facets[f].E != s.E ||
              glm::dot(facets[f].normal, s.normal) < kCosTolerance ||
              std::abs(glm::dot(facets[f].centre - s.centre, s.normal)) > 1e-3 * meshSize)
            continue;
          taken[f] = 1;
          stack.push_back(f);
        }
    }
    planes.push_back(std::move(plane));
  }
  return planes;
}

// The plane's corners projected onto the plane through its first corner, so that the hull is
// planar to rounding; the hull taken in a frame of that plane, counter-clockwise about the
// plane's normal. Empty for a plane whose corners are all on one line.
std::vector<Vec3> hullOf(const RadiosityMesh& mesh, const Plane& plane) {
  const Vec3 normal = glm::normalize(plane.normalTimesArea);
  if (!isFinite(normal)) return {};
  const Vec3 origin = mesh.nodes[mesh.elements[plane.elements[0]].corners[0]].position;
  Vec3 t, b;
  orthonormalBasis(normal, t, b);
  std::vector<Vec3> corners;
  std::vector<Vec2> flat;
  for (uint32_t e : plane.elements)
    for (uint32_t node : mesh.elements[e].corners) {
      const Vec3 q = mesh.nodes[node].position - origin;
      corners.push_back(origin + q - glm::dot(q, normal) * normal);
      flat.push_back({glm::dot(q, t), glm::dot(q, b)});
    }
  std::vector<Vec3> hull;
  for (int i : convexHull2(flat)) hull.push_back(corners[size_t(i)]);
  // Corners within rounding of the line through their neighbours (a mesh's vertices along a
  // straight edge, in float) cost a test per ray and change nothing: dropped. What is left is
  // still convex, and the hull need only be some convex polygon close to the plane.
  Bounds bounds;
  for (const Vec3& v : hull) bounds.extend(v);
  const double tiny = 1e-9 * bounds.diagonal() * bounds.diagonal();
  for (size_t i = 0; hull.size() > 3 && i < hull.size();) {
    const Vec3& before = hull[(i + hull.size() - 1) % hull.size()];
    const Vec3& after = hull[(i + 1) % hull.size()];
    if (glm::length(glm::cross(hull[i] - before, after - hull[i])) <= tiny)
      hull.erase(hull.begin() + std::ptrdiff_t(i));
    else
      ++i;
  }
  // A round plane's hull has many corners: every k-th of them is a convex polygon too.
  if (hull.size() > OccludingPolygons::kMaxCorners) {
    const size_t step = (hull.size() + OccludingPolygons::kMaxCorners - 1) / OccludingPolygons::kMaxCorners;
    std::vector<Vec3> fewer;
    for (size_t i = 0; i < hull.size(); i += step) fewer.push_back(hull[i]);
    hull = std::move(fewer);
  }
  if (hull.size() < 3 || !(area(hull) > 0.0)) return {};
  if (glm::dot(unitNormal(hull), normal) < 0.0) std::reverse(hull.begin(), hull.end());
  return hull;
}

// The grid over the hull, in a frame of its plane, and each cell's area mean of the elements'
// B - E (by their centres); a cell no centre falls in takes the plane's mean.
SceneControl::HullRadiosity radiosityOn(const Plane& plane, const std::vector<Facet>& facets,
                                        const std::vector<Vec3>& hull, int cells) {
  SceneControl::HullRadiosity r;
  r.origin = hull[0];
  orthonormalBasis(unitNormal(hull), r.t, r.b);
  Vec2 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
  for (const Vec3& v : hull) {
    const Vec2 p(glm::dot(v - r.origin, r.t), glm::dot(v - r.origin, r.b));
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  const Vec2 extent = glm::max(high - low, Vec2(1e-300));
  r.columns = std::clamp(int(std::lround(std::sqrt(cells * extent.x / extent.y))), 1, cells);
  r.rows = std::clamp(int(std::lround(double(cells) / r.columns)), 1, cells);
  r.low = low;
  r.cellSize = extent / Vec2(r.columns, r.rows);
  const size_t count = size_t(r.columns) * size_t(r.rows);
  std::vector<Rgb> sum(count, Rgb(0.0));
  std::vector<double> weight(count, 0.0);
  for (uint32_t e : plane.elements) {
    const size_t cell = r.cellOf(facets[e].centre);
    sum[cell] += facets[e].area * facets[e].reflected;
    weight[cell] += facets[e].area;
  }
  for (size_t cell = 0; cell < count; ++cell)
    r.reflected.push_back(weight[cell] > 0.0 ? sum[cell] / weight[cell] : plane.reflectedTimesArea / plane.area);
  return r;
}

}  // namespace

size_t SceneControl::HullRadiosity::cellOf(const Vec3& p) const {
  const Vec3 q = p - origin;
  const int column = std::clamp(int(std::floor((glm::dot(q, t) - low.x) / cellSize.x)), 0, columns - 1);
  const int row = std::clamp(int(std::floor((glm::dot(q, b) - low.y) / cellSize.y)), 0, rows - 1);
  return size_t(row) * size_t(columns) + size_t(column);
}

SceneControl::SceneControl(const RadiosityMesh& mesh) : hulls_({}) {
  Bounds bounds;
  for (const Node& node : mesh.nodes) bounds.extend(node.position);
  const double meshSize = std::max(bounds.diagonal(), 1e-300);
  std::vector<Facet> facets(mesh.elements.size());
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& element = mesh.elements[e];
    const std::vector<Vec3> corners = mesh.cornerPositions(e);
    Facet& f = facets[e];
    f.area = area(corners);
    f.normal = unitNormal(corners);
    f.centre = centroid(corners);
    f.E = mesh.materials[size_t(element.material)].E;
    for (uint32_t node : element.corners) f.reflected += mesh.nodes[node].B;
    f.reflected = f.reflected / double(element.corners.size()) - f.E;
  }

  // The emitters first (the direct control needs their hulls), then the planes that carry the
  // most light: each hull costs a clipped Lambert sum per point and a ray test per sample, so
  // only the first OccludingPolygons::kMaxPolygons become hulls (any h keeps the estimate
  // unbiased; those left out would have reduced the variance least).
  std::vector<Plane> planes = growPlanes(mesh, facets, meshSize);
  auto emits = [](const Plane& p) { return meanOf(p.E) > 0.0; };
  auto weight = [](const Plane& p) { return std::abs(meanOf(p.reflectedTimesArea)); };
  std::stable_sort(planes.begin(), planes.end(), [&](const Plane& a, const Plane& b) {
    return emits(a) != emits(b) ? emits(a) : weight(a) > weight(b);
  });

  // Cells where B^ varies: the grid budget shared by the planes in proportion to the area
  // integral of (B - mean)^2 over each (the variance a single value leaves).
  std::vector<double> spread(planes.size(), 0.0);
  double totalSpread = 0.0;
  for (size_t j = 0; j < planes.size() && j < OccludingPolygons::kMaxPolygons; ++j) {
    const Rgb mean = planes[j].reflectedTimesArea / planes[j].area;
    for (uint32_t e : planes[j].elements) {
      const double d = meanOf(facets[e].reflected - mean);
      spread[j] += facets[e].area * d * d;
    }
    totalSpread += spread[j];
  }
  std::vector<std::vector<Vec3>> hulls;
  std::vector<uint8_t> tracked(mesh.elements.size(), 0);
  for (size_t j = 0; j < planes.size() && hulls.size() < OccludingPolygons::kMaxPolygons; ++j) {
    const Plane& plane = planes[j];
    const int cells = totalSpread > 0.0 ? std::max(1, int(std::lround(kCellBudget * spread[j] / totalSpread))) : 1;
    std::vector<Vec3> hull = hullOf(mesh, plane);
    if (hull.empty()) continue;
    const uint32_t index = uint32_t(hulls.size());
    // An emitter's hull stands for the emitter in the direct control only where it is the
    // emitter (convex): the control must be sampled over what EmitterSampler samples.
    const bool convexEmitter = emits(plane) && area(hull) <= plane.area * (1.0 + 1e-6);
    radiosities_.push_back(radiosityOn(plane, facets, hull, emits(plane) ? 1 : cells));
    radiosities_.back().emitted = convexEmitter ? plane.E : Rgb(0.0);
    if (convexEmitter)
      for (uint32_t e : plane.elements) {
        hullOfEmitter_[e] = index;
        tracked[e] = 1;
      }
    hulls.push_back(std::move(hull));
  }
  hulls_ = OccludingPolygons(hulls);

  // The emitters no hull stands for, by plane and material.
  std::map<std::tuple<long long, long long, long long, long long, int>, std::vector<std::vector<Vec3>>> groups;
  auto q = [](double v, double quantum) { return (long long)std::llround(v / quantum); };
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    if (tracked[e] || !(meanOf(facets[e].E) > 0.0) || !(facets[e].area > 0.0)) continue;
    const Vec3& n = facets[e].normal;
    groups[{q(n.x, 1e-4), q(n.y, 1e-4), q(n.z, 1e-4), q(glm::dot(n, facets[e].centre), 1e-6 * meshSize),
            mesh.elements[e].material}]
        .push_back(mesh.cornerPositions(e));
  }
  for (const auto& [key, polygons] : groups)
    unoccluded_.push_back({PatchFormFactor(polygons), mesh.materials[size_t(std::get<4>(key))].E});
}

Rgb SceneControl::pieceIntegral(const HullRadiosity& hull, const Vec3& x, const Vec3& n,
                                const std::vector<Vec3>& piece) const {
  if (hull.reflected.size() == 1)
    return (hull.reflected[0] + hull.emitted) * formFactorAboveHorizon(x, n, piece.data(), piece.size());
  // Column by column, then row by row: the grid's first and last lines stay open, so that
  // the cells cover the piece whatever rounding does at the hull's edges (cellOf clamps alike).
  thread_local std::vector<Vec3> strip, cell, scratch;
  // `polygon` cut to slab `index` of `count` along `axis`, from `start` in steps of `step`.
  auto slab = [&](std::vector<Vec3>& polygon, const Vec3& axis, double start, double step, int index, int count) {
    if (index > 0) {
      clipToHalfSpace(polygon, hull.origin + (start + index * step) * axis, axis, scratch);
      std::swap(polygon, scratch);
    }
    if (index + 1 < count) {
      clipToHalfSpace(polygon, hull.origin + (start + (index + 1) * step) * axis, -axis, scratch);
      std::swap(polygon, scratch);
    }
    return polygon.size() >= 3;
  };
  Rgb sum(0.0);
  for (int column = 0; column < hull.columns; ++column) {
    strip = piece;
    if (!slab(strip, hull.t, hull.low.x, hull.cellSize.x, column, hull.columns)) continue;
    for (int row = 0; row < hull.rows; ++row) {
      cell = strip;
      if (!slab(cell, hull.b, hull.low.y, hull.cellSize.y, row, hull.rows)) continue;
      sum += (hull.reflected[size_t(row) * size_t(hull.columns) + size_t(column)] + hull.emitted) *
             formFactorAboveHorizon(x, n, cell.data(), cell.size());
    }
  }
  return sum;
}

Rgb SceneControl::integral(const Vec3& x, const Vec3& n, uint64_t facing) const {
  Rgb sum(0.0);
  hulls_.visibleParts(x, n, facing, [&](size_t i, const std::vector<Vec3>& piece) {
    sum += pieceIntegral(radiosities_[i], x, n, piece);
  });
  for (const UnoccludedEmitter& emitter : unoccluded_) sum += emitter.E * emitter.formFactor.from(x, n);
  return sum;
}

Rgb SceneControl::along(const Vec3& x, const Vec3& direction, uint64_t facing) const {
  Rgb sum(0.0);
  for (uint64_t seen = hulls_.seenAlong(x, direction, facing); seen != 0; seen &= seen - 1) {
    const HullRadiosity& hull = radiosities_[size_t(__builtin_ctzll(seen))];
    sum += hull.reflected.size() == 1
               ? hull.reflected[0]
               : hull.reflected[hull.cellOf(hulls_.pointAlong(size_t(__builtin_ctzll(seen)), x, direction))];
  }
  return sum;
}

bool SceneControl::emitterSeen(const Vec3& x, const EmitterSample& sample, uint64_t facing) const {
  const auto hull = hullOfEmitter_.find(sample.element);
  if (hull == hullOfEmitter_.end()) return true;
  return (facing >> hull->second & 1u) && hulls_.seenAt(x, sample.position, facing, hull->second);
}

}  // namespace radview
