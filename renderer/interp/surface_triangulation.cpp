#include "interp/surface_triangulation.h"

#include "core/error.h"
#include "core/parallel_for.h"
#include "geom/polygon.h"
#include "geom/triangulate_cgal.h"
#include "interp/bezier_triangle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace radview {

namespace {

bool lexicographicallyLess(const Vec3& a, const Vec3& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

// A corner of an element's boundary after T-vertex insertion: its node, and the element edge
// the boundary segment starting at it belongs to.
struct BoundaryVertex {
  uint32_t node;
  uint32_t elementEdge;
};

std::vector<BoundaryVertex> boundaryWithTVertices(const RadiosityMesh& mesh, const MeshTopology& topology,
                                                  uint32_t element) {
  const Element& e = mesh.elements[element];
  std::vector<BoundaryVertex> boundary;
  boundary.reserve(e.corners.size());
  const std::vector<TVertex>& all = topology.tVertices();
  // MeshTopology lists T-vertices by element: this element's are one run of them.
  const auto run =
      std::lower_bound(all.begin(), all.end(), element, [](const TVertex& v, uint32_t el) { return v.element < el; });
  if (e.order() != ElementOrder::Linear || run == all.end() || run->element != element) {
    for (uint32_t k = 0; k < e.corners.size(); ++k) boundary.push_back({e.corners[k], k});
    return boundary;
  }
  std::vector<std::vector<std::pair<double, uint32_t>>> inserted(e.corners.size());
  // A node the element across the same edge has as a corner is no T-vertex: that element
  // shares the whole edge, so the node is the apex of a cap (a triangle thinner than the 1e-5
  // relative tolerance of MeshTopology's on-edge test, aspect ratio above ~1e5). Inserted, it
  // made this element overlap the cap and cut both off from their neighbours (no C1 across
  // the cap's edges, found by extremes_test's caps of aspect 1e5 .. 1e7).
  auto isCapApex = [&](const TVertex& t) {
    const int64_t across = topology.neighbour(element, t.edge);
    if (across < 0) return false;
    for (uint32_t c : mesh.elements[size_t(across)].corners)
      if (topology.positionId(c) == topology.positionId(t.node)) return true;
    return false;
  };
  for (auto t = run; t != all.end() && t->element == element; ++t)
    if (!isCapApex(*t)) inserted[t->edge].push_back({t->t, t->node});
  for (uint32_t k = 0; k < e.corners.size(); ++k) {
    boundary.push_back({e.corners[k], k});
    std::sort(inserted[k].begin(), inserted[k].end());
    for (const auto& [t, node] : inserted[k]) boundary.push_back({node, k});
  }
  return boundary;
}

// Triangles of a simple polygon, as indices into it: orientation-independent (see header).
// The points CGAL sees are a function of the polygon's shape alone, not of its size or place:
// measured from the start corner along its outgoing edge, in units of the polygon's extent,
// rounded to 2^-40 of it. A square's corners are cocircular, a tie of the Delaunay test, and
// the positions' rounding decided it: the extreme box scaled by 1e-6 (not exact in binary) had
// 411 of its triangles cut along the other diagonal, and the C1 methods built on them changed
// by up to 10 times the element's largest value (scale_invariance_test). Rounded, near ties are
// exact ties at every scale, broken the same way at each (convexQuadDelaunay says how). 2^-40
// of the extent is well above double round-off (2^-52), and moving a vertex by half of it
// brings no two together: that is far inside MeshTopology's weld distance (1e-7 of the mesh's
// diagonal).
std::vector<std::array<int, 3>> delaunayTriangles(const std::vector<Vec3>& polygon) {
  if (polygon.size() == 3) return {{0, 1, 2}};
  PlaneFrame frame = planeFrame(polygon);
  const size_t n = polygon.size();
  size_t start = 0;
  for (size_t i = 1; i < n; ++i)
    if (lexicographicallyLess(polygon[i], polygon[start])) start = i;
  // The start corner's outgoing edge, not planeFrame's longest edge: two edges of one length
  // (a square's) make that choice a matter of rounding. A zero edge keeps planeFrame's axis
  // (CGAL then reports the coincident vertices).
  const Vec3 edge = polygon[(start + 1) % n] - polygon[start];
  const Vec3 inPlane = edge - glm::dot(edge, frame.n) * frame.n;
  if (glm::length(inPlane) > 0.0) frame.u = glm::normalize(inPlane);
  frame.v = glm::cross(frame.n, frame.u);
  frame.origin = polygon[start];
  std::vector<Vec2> flat(n);
  double extent = 0.0;
  for (size_t i = 0; i < n; ++i) {
    flat[i] = frame.project(polygon[(start + i) % n]);
    extent = std::max({extent, std::abs(flat[i].x), std::abs(flat[i].y)});
  }
  for (Vec2& p : flat) p = glm::round(std::ldexp(1.0, 40) / extent * p);
  // Most elements are convex quads: their two triangles without building a triangulation.
  const auto quad = n == 4 ? convexQuadDelaunay({flat[0], flat[1], flat[2], flat[3]}) : std::nullopt;
  std::vector<std::array<int, 3>> triangles =
      quad ? std::vector<std::array<int, 3>>(quad->begin(), quad->end()) : constrainedDelaunayTriangulation(flat);
  for (auto& t : triangles)
    for (int& v : t) v = static_cast<int>((v + start) % n);
  return triangles;
}

}  // namespace

SurfaceTriangulation::SurfaceTriangulation(const RadiosityMesh& mesh)
    : SurfaceTriangulation(mesh, std::make_shared<const MeshTopology>(mesh)) {}

SurfaceTriangulation::SurfaceTriangulation(const RadiosityMesh& mesh, std::shared_ptr<const MeshTopology> topology)
    : mesh_(mesh), topology_(std::move(topology)) {
  firstTriangle_.reserve(mesh.elements.size() + 1);
  // Which element edge each triangle edge lies on (-1: a diagonal inside the element).
  // Elements are cut in blocks on every core, each block into its own lists, joined in order.
  struct Cut {
    std::vector<SurfaceTriangle> triangles;
    std::vector<std::array<int64_t, 3>> onElementEdge;
    std::vector<uint32_t> countOf;  // per element of the block
  };
  constexpr size_t kBlock = 1024;
  std::vector<Cut> cuts((mesh.elements.size() + kBlock - 1) / kBlock);
  parallelFor(
      cuts.size(),
      [&](size_t block) {
        Cut& cut = cuts[block];
        for (uint32_t e = uint32_t(block * kBlock); e < std::min(mesh.elements.size(), (block + 1) * kBlock); ++e) {
          const std::vector<BoundaryVertex> boundary = boundaryWithTVertices(mesh, *topology_, e);
          std::vector<Vec3> polygon;
          for (const BoundaryVertex& v : boundary) polygon.push_back(mesh.nodes[v.node].position);
          const size_t n = boundary.size();
          const std::vector<std::array<int, 3>> triangles = delaunayTriangles(polygon);
          for (const auto& t : triangles) {
            SurfaceTriangle triangle;
            triangle.element = e;
            std::array<int64_t, 3> edges{};
            for (int k = 0; k < 3; ++k) {
              triangle.node[k] = boundary[t[k]].node;
              const bool boundarySegment = size_t(t[(k + 1) % 3]) == (size_t(t[k]) + 1) % n;
              edges[k] = boundarySegment ? int64_t(boundary[t[k]].elementEdge) : -1;
            }
            cut.triangles.push_back(triangle);
            cut.onElementEdge.push_back(edges);
          }
          cut.countOf.push_back(uint32_t(triangles.size()));
        }
      },
      1);
  size_t total = 0;
  for (const Cut& cut : cuts) total += cut.triangles.size();
  triangles_.reserve(total);
  std::vector<std::array<int64_t, 3>> onElementEdge;
  onElementEdge.reserve(total);
  for (Cut& cut : cuts) {
    uint32_t first = uint32_t(triangles_.size());
    for (uint32_t count : cut.countOf) {
      firstTriangle_.push_back(first);
      first += count;
    }
    triangles_.insert(triangles_.end(), cut.triangles.begin(), cut.triangles.end());
    onElementEdge.insert(onElementEdge.end(), cut.onElementEdge.begin(), cut.onElementEdge.end());
    cut = {};
  }
  firstTriangle_.push_back(uint32_t(triangles_.size()));

  // Neighbours: triangle edges matched through position ids (so the two sides of a C-1 edge,
  // which have distinct nodes, still meet), kept only between triangles of one plane.
  // Every triangle edge once, ordered by its end positions, then by triangle and edge: each
  // run of equal ends is one edge and its sides.
  struct Side {
    uint32_t a, b, triangle, edge;
    bool operator<(const Side& o) const {
      return std::tie(a, b, triangle, edge) < std::tie(o.a, o.b, o.triangle, o.edge);
    }
  };
  // Counted into place by their smaller end (the sides of one end are a handful), then each
  // run sorted: linear in the triangles, where one sort of them all was a third of the set-up.
  std::vector<uint32_t> startOf(size_t(topology_->positionCount()) + 1, 0);
  for (const SurfaceTriangle& triangle : triangles_)
    for (uint32_t k = 0; k < 3; ++k)
      ++startOf[size_t(std::min(topology_->positionId(triangle.node[k]),
                                topology_->positionId(triangle.node[(k + 1) % 3]))) + 1];
  for (size_t i = 1; i < startOf.size(); ++i) startOf[i] += startOf[i - 1];
  std::vector<Side> sides(3 * triangles_.size());
  {
    std::vector<uint32_t> next(startOf.begin(), startOf.end());
    for (uint32_t t = 0; t < triangles_.size(); ++t)
      for (uint32_t k = 0; k < 3; ++k) {
        const uint32_t a = topology_->positionId(triangles_[t].node[k]);
        const uint32_t b = topology_->positionId(triangles_[t].node[(k + 1) % 3]);
        sides[next[std::min(a, b)]++] = {std::min(a, b), std::max(a, b), t, k};
      }
  }
  auto smallestHeight = [&](uint32_t triangle) {
    const auto p = positions(triangle);
    const double longest = std::max({glm::length(p[1] - p[0]), glm::length(p[2] - p[1]), glm::length(p[0] - p[2])});
    return longest > 0.0 ? glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) / longest : 0.0;
  };
  // Each run of one smaller end on its own: a triangle edge is in one run only, so no two write
  // the same neighbour.
  auto link = [&](size_t first) {
    const uint32_t t0 = sides[first].triangle, t1 = sides[first + 1].triangle;
    const int k0 = int(sides[first].edge), k1 = int(sides[first + 1].edge);
    // The far vertex of one is measured from the plane of the other whose normal is the better
    // conditioned, the one with the larger smallest height (a triangle's normal is good to
    // ~eps |x| / that height). Measured from a sliver's plane, a planar neighbour's far vertex
    // would be off by that error times the neighbour's size, and the edge would read as a
    // crease: no neighbour, no C1 across it (a sliver of height 6e-8 beside a triangle of size
    // 0.1, c1_mesh_test's sliver meshes).
    const bool firstIsReference = smallestHeight(t0) >= smallestHeight(t1);
    const uint32_t reference = firstIsReference ? t0 : t1, other = firstIsReference ? t1 : t0;
    const int otherEdge = firstIsReference ? k1 : k0;
    const auto p0 = positions(reference);
    const Vec3 far = positions(other)[(otherEdge + 2) % 3];
    const double size = glm::length(p0[1] - p0[0]) + glm::length(p0[2] - p0[1]);
    const Vec3 n0 = normal(reference);
    // Each position is only good to its rounding, delta = eps |x|, which tilts n0 by up to
    // ~delta / (its smallest height) and so moves the far vertex off the plane by that times
    // its distance. Near the origin 1e-9 of the size covers it; 1e5 from it, a tilted mesh
    // 1e-3 across (delta 2e-11, 1e-7 of its triangles) had 176 of its 192 links read as
    // creases, and the C1 methods changed by 5e-4 of the values (scale_invariance_test).
    double largest = 0.0;
    for (const Vec3& p : {p0[0], p0[1], p0[2], far})
      for (int i = 0; i < 3; ++i) largest = std::max(largest, std::abs(p[i]));
    const double delta = std::numeric_limits<double>::epsilon() * largest;
    const double lever = glm::length(far - p0[0]) / smallestHeight(reference);
    const double tolerance = 1e-9 * size + 4.0 * delta * (1.0 + lever);
    const bool samePlane = glm::dot(n0, normal(other)) > 1.0 - 1e-9 && std::abs(glm::dot(far - p0[0], n0)) <= tolerance;
    if (!samePlane) return;
    SurfaceTriangle& A = triangles_[t0];
    SurfaceTriangle& B = triangles_[t1];
    A.neighbour[k0] = int32_t(t1);  // triangles are far fewer than 2^31 (core/limits.h)
    B.neighbour[k1] = int32_t(t0);
    // Edge k0 of A runs a -> b; the same edge of B runs b -> a.
    const bool sameNodes = A.node[k0] == B.node[(k1 + 1) % 3] && A.node[(k0 + 1) % 3] == B.node[k1];
    Continuity order = sameNodes ? Continuity::C1 : Continuity::Cm1;
    for (const Side& side : {sides[first], sides[first + 1]}) {
      const uint32_t t = side.triangle;
      const int64_t elementEdge = onElementEdge[t][side.edge];
      if (elementEdge >= 0) {
        const Continuity tagged =
            topology_->edges()[topology_->edgeIndex(triangles_[t].element, uint32_t(elementEdge))].continuity;
        order = std::min(order, tagged);
      }
    }
    A.continuity[k0] = B.continuity[k1] = order;
  };
  parallelFor(
      startOf.size() - 1,
      [&](size_t a) {
        const auto begin = sides.begin() + startOf[a], end = sides.begin() + startOf[a + 1];
        std::sort(begin, end);
        for (auto first = begin, last = begin; first != end; first = last) {
          for (last = first + 1; last != end && last->b == first->b;) ++last;
          if (last - first == 2) link(size_t(first - sides.begin()));
        }
      },
      4096);
}

std::array<Vec3, 3> SurfaceTriangulation::positions(uint32_t triangle) const {
  const auto& n = triangles_[triangle].node;
  return {mesh_.nodes[n[0]].position, mesh_.nodes[n[1]].position, mesh_.nodes[n[2]].position};
}

Vec3 SurfaceTriangulation::normal(uint32_t triangle) const {
  const auto p = positions(triangle);
  const Vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : Vec3(0.0);
}

int SurfaceTriangulation::cornerAt(uint32_t triangle, uint32_t node) const {
  const uint32_t wanted = topology_->positionId(node);
  for (int k = 0; k < 3; ++k)
    if (topology_->positionId(triangles_[triangle].node[k]) == wanted) return k;
  return -1;
}

SurfaceTriangulation::Location SurfaceTriangulation::locate(uint32_t element, const Vec3& x) const {
  Location best;
  double bestInside = -std::numeric_limits<double>::infinity();
  for (uint32_t t : trianglesOf(element)) {
    const auto p = positions(t);
    const Vec3 w = barycentricFrame(p)(x);
    const double inside = std::min(w.x, std::min(w.y, w.z));
    if (inside > bestInside) {
      bestInside = inside;
      best = {t, w};
    }
  }
  return best;
}

}  // namespace radview
