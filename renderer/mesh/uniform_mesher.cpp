#include "mesh/uniform_mesher.h"

#include "core/error.h"
#include "geom/polygon.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

namespace radview {

namespace {

// How one polygon is cut: a bilinear grid of its quad, or a subdivision of its triangles.
struct PolygonPlan {
  bool grid = false;
  std::vector<std::array<int, 3>> triangles;  // when not a grid; empty for a zero-area polygon
  double lengthU = 0.0, lengthV = 0.0;        // grid: longer edge of each opposite pair
  double longestEdge = 0.0;                   // triangles: longest edge of any of them
};

// Pieces an edge of this length is cut into; double, so absurd sizes cannot overflow.
double divisions(double length, double elementSize) { return std::max(1.0, std::ceil(length / elementSize)); }

double elementCount(const PolygonPlan& plan, double elementSize) {
  if (plan.grid) return divisions(plan.lengthU, elementSize) * divisions(plan.lengthV, elementSize);
  const double n = divisions(plan.longestEdge, elementSize);
  return double(plan.triangles.size()) * n * n;
}

double elementCount(const std::vector<PolygonPlan>& plans, double elementSize) {
  double total = 0.0;
  for (const PolygonPlan& plan : plans) total += elementCount(plan, elementSize);
  return total;
}

PolygonPlan planPolygon(const std::vector<Vec3>& v) {
  PolygonPlan plan;
  if (unitNormal(v) == Vec3(0.0)) return plan;
  auto length = [&](int i, int j) { return glm::distance(v[i], v[j]); };
  // A warped quad would give warped elements; triangles are always flat.
  if (v.size() == 4 && isStrictlyConvex(v) && planarityError(v) <= 1e-4 * std::max(length(0, 2), length(1, 3))) {
    plan.grid = true;
    plan.lengthU = std::max(length(0, 1), length(3, 2));
    plan.lengthV = std::max(length(1, 2), length(0, 3));
    return plan;
  }
  plan.triangles = triangulatePolygon(v);
  for (const auto& t : plan.triangles)
    for (int k = 0; k < 3; ++k) plan.longestEdge = std::max(plan.longestEdge, length(t[k], t[(k + 1) % 3]));
  return plan;
}

// The smallest element size whose mesh fits under the cap, rounded up to 3 significant digits,
// or 0 if none does (more polygons than the cap). The count only falls as the size grows
// (every ceil does), so bisection finds it; geometric, as the sizes may span many decades.
double sizeThatFits(const std::vector<PolygonPlan>& plans, double elementSize) {
  auto fits = [&](double size) { return elementCount(plans, size) <= double(kMaxMeshElements); };
  double enough = 0.0;  // no edge longer than this: every polygon gets its fewest elements
  for (const PolygonPlan& plan : plans) enough = std::max({enough, plan.lengthU, plan.lengthV, plan.longestEdge});
  if (!fits(enough)) return 0.0;
  double tooSmall = elementSize;
  for (int i = 0; i < 200; ++i) {
    const double middle = std::sqrt(tooSmall * enough);
    (fits(middle) ? enough : tooSmall) = middle;
  }
  const double unit = std::pow(10.0, std::floor(std::log10(enough)) - 2);
  return std::ceil(enough / unit) * unit;
}

// An element count as text: exact while it is an integer a double holds exactly.
std::string countText(double count) {
  std::ostringstream os;
  if (count < 1e15)
    os << static_cast<long long>(count);
  else
    os << count;
  return os.str();
}

void addElement(RadiosityMesh& mesh, std::vector<uint32_t> corners, int surface, int material) {
  Element e;
  e.corners = std::move(corners);
  e.surface = surface;
  e.material = material;
  mesh.elements.push_back(std::move(e));
}

uint32_t addNode(RadiosityMesh& mesh, const Vec3& position) {
  Node node;
  node.position = position;
  mesh.nodes.push_back(node);
  return uint32_t(mesh.nodes.size() - 1);
}

// Bilinear subdivision of the quad v0 v1 v2 v3: node (i, j) at s = i/n along v0 -> v1, t = j/m
// along v0 -> v3; elements keep the quad's orientation.
void meshQuadGrid(RadiosityMesh& mesh, const std::vector<Vec3>& v, int n, int m, int surface, int material) {
  const uint32_t first = uint32_t(mesh.nodes.size());
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) {
      const double s = double(i) / n, t = double(j) / m;
      addNode(mesh, (1 - s) * (1 - t) * v[0] + s * (1 - t) * v[1] + s * t * v[2] + (1 - s) * t * v[3]);
    }
  auto node = [&](int i, int j) { return first + uint32_t(i * (m + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j)
      addElement(mesh, {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)}, surface, material);
}

// Regular subdivision of the polygon's triangles into n^2 triangles each. A node on an edge is
// computed from the edge's lower-indexed end whichever triangle asks, so the two triangles on a
// shared edge produce bitwise equal positions, and the nodes are welded by exact position.
void meshTriangles(RadiosityMesh& mesh, const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& triangles,
                   int n, int surface, int material) {
  std::map<std::array<double, 3>, uint32_t> nodeAt;
  auto nodeOf = [&](const Vec3& p) {
    auto [it, added] = nodeAt.emplace(std::array<double, 3>{p.x, p.y, p.z}, uint32_t(mesh.nodes.size()));
    if (added) addNode(mesh, p);
    return it->second;
  };
  // The point k/n of the way from vertex p to vertex q.
  auto onEdge = [&](int p, int q, int k) {
    if (p > q) {
      std::swap(p, q);
      k = n - k;
    }
    if (k == 0) return v[p];
    if (k == n) return v[q];
    return v[p] + (double(k) / n) * (v[q] - v[p]);
  };
  for (const auto& triangle : triangles) {
    // Not a structured binding: C++17 lambdas cannot capture those.
    const int a = triangle[0], b = triangle[1], c = triangle[2];
    // Node (i, j): i steps towards b, j towards c.
    auto at = [&](int i, int j) {
      if (j == 0) return nodeOf(onEdge(a, b, i));
      if (i == 0) return nodeOf(onEdge(a, c, j));
      if (i + j == n) return nodeOf(onEdge(b, c, j));
      return nodeOf(v[a] + (double(i) / n) * (v[b] - v[a]) + (double(j) / n) * (v[c] - v[a]));
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        addElement(mesh, {at(i, j), at(i + 1, j), at(i, j + 1)}, surface, material);
        if (i + j + 1 < n) addElement(mesh, {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, surface, material);
      }
  }
}

}  // namespace

RadiosityMesh meshUniformly(const Scene& scene, double elementSize) {
  if (!(elementSize > 0.0) || !std::isfinite(elementSize)) {
    std::ostringstream os;
    os << "element size " << elementSize << " is not a positive finite length";
    throw Error(os.str());
  }
  std::vector<PolygonPlan> plans;
  plans.reserve(scene.polygons.size());
  for (size_t p = 0; p < scene.polygons.size(); ++p) {
    try {
      plans.push_back(planPolygon(scene.polygons[p].vertices));
    } catch (const Error& e) {
      throw Error("polygon " + std::to_string(p) + ": " + e.what());
    }
  }
  const double total = elementCount(plans, elementSize);
  if (total > double(kMaxMeshElements)) {
    std::ostringstream os;
    os << "element size " << elementSize << " gives " << countText(total) << " elements, more than radview's limit of "
       << kMaxMeshElements << "; ";
    const double fitting = sizeThatFits(plans, elementSize);
    if (fitting > 0.0) {
      os << "an element size of " << fitting << " or more fits";
    } else {
      os << "no element size fits (too many polygons)";
    }
    throw Error(os.str());
  }

  RadiosityMesh mesh;
  mesh.materials = scene.materials;
  mesh.elements.reserve(size_t(total));
  for (size_t p = 0; p < plans.size(); ++p) {
    const PolygonPlan& plan = plans[p];
    const Polygon& polygon = scene.polygons[p];
    if (plan.grid) {
      meshQuadGrid(mesh, polygon.vertices, int(divisions(plan.lengthU, elementSize)),
                   int(divisions(plan.lengthV, elementSize)), int(p), polygon.material);
    } else if (!plan.triangles.empty()) {
      meshTriangles(mesh, polygon.vertices, plan.triangles, int(divisions(plan.longestEdge, elementSize)), int(p),
                    polygon.material);
    }
  }
  return mesh;
}

}  // namespace radview
