#pragma once
// Meshes for the interpolant tests: planar triangle and quad meshes lying in an arbitrary
// plane in 3D (so nothing relies on z = 0), jittered, with values from a given function.
#include "interp/interpolant.h"
#include "mesh/radiosity_mesh.h"
#include "mesh/topology.h"
#include "tests/test_print.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace radview::test {

// A point of the plane from its 2D coordinates: origin + x u + y v.
struct Plane {
  Vec3 origin{0.3, -0.2, 0.1};
  Vec3 u = glm::normalize(Vec3(1.0, 0.4, -0.3));
  Vec3 v = glm::normalize(glm::cross(Vec3(0.2, 0.5, 1.0), Vec3(1.0, 0.4, -0.3)));
  Vec3 at(double x, double y) const { return origin + x * u + y * v; }
  Vec2 coords(const Vec3& p) const { return {glm::dot(p - origin, u), glm::dot(p - origin, v)}; }
};

using Field = std::function<Rgb(const Vec2&)>;

// The cells of a grid whose (columns + 1) x (rows + 1) nodes are numbered row by row: each a
// quad, or two triangles cut along the diagonal a c where alongAC(i, j), else along b d
// (alongAC is called once per cell, row by row, and only for triangles).
inline void addGridCells(RadiosityMesh& mesh, int columns, int rows, bool quads,
                         const std::function<bool(int, int)>& alongAC) {
  auto id = [columns](int i, int j) { return uint32_t(j * (columns + 1) + i); };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (quads) {
        mesh.elements.push_back(Element{{a, b, c, d}, {}, 0, 0});
      } else if (alongAC(i, j)) {
        mesh.elements.push_back(Element{{a, b, c}, {}, 0, 0});
        mesh.elements.push_back(Element{{a, c, d}, {}, 0, 0});
      } else {
        mesh.elements.push_back(Element{{a, b, d}, {}, 0, 0});
        mesh.elements.push_back(Element{{b, c, d}, {}, 0, 0});
      }
    }
}

// n x n cells over [0,1]^2, nodes jittered by up to `jitter` of a cell (boundary nodes stay on
// the boundary), each cell cut into two triangles along a random diagonal, or kept as a quad.
inline RadiosityMesh gridMesh(int n, bool quads, double jitter, const Field& f, uint32_t seed,
                              const Plane& plane = {}) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter, jitter);
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
  const double h = 1.0 / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      Vec2 p(i * h, j * h);
      if (i > 0 && i < n) p.x += offset(random) * h;
      if (j > 0 && j < n) p.y += offset(random) * h;
      mesh.nodes.push_back({plane.at(p.x, p.y), f(p), {}});
    }
  addGridCells(mesh, n, n, quads, [&](int, int) { return random() % 2 != 0; });
  return mesh;
}

// Turns every element of a linear mesh into a quadratic one with straight edges: a mid-edge
// node at each edge midpoint (shared between neighbours), valued by f.
inline RadiosityMesh withMidEdgeNodes(RadiosityMesh mesh, const Field& f, const Plane& plane = {}) {
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
  for (Element& e : mesh.elements) {
    const size_t n = e.corners.size();
    e.midEdge.resize(n);
    for (size_t k = 0; k < n; ++k) {
      const uint32_t a = e.corners[k], b = e.corners[(k + 1) % n];
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it == mid.end()) {
        const Vec3 p = 0.5 * (mesh.nodes[a].position + mesh.nodes[b].position);
        it = mid.emplace(key, uint32_t(mesh.nodes.size())).first;
        mesh.nodes.push_back({p, f(plane.coords(p)), {}});
      }
      e.midEdge[k] = it->second;
    }
  }
  return mesh;
}

// An interpolation method with its options, named for failure messages.
struct MethodCase {
  std::string name;
  Method method;
  InterpolantOptions options{};
};
inline MethodCase cloughTocher(CloughTocherVariant variant, bool storedGradients = true) {
  InterpolantOptions options;
  options.cloughTocher = variant;
  options.useStoredGradients = storedGradients;
  return {variant == CloughTocherVariant::Book ? "clough-tocher (book)" : "clough-tocher (affine)",
          Method::CloughTocher, options};
}
// The C1 methods: Powell-Sabin and both Clough-Tocher variants.
inline std::vector<MethodCase> c1Methods(bool storedGradients = true) {
  InterpolantOptions options;
  options.useStoredGradients = storedGradients;
  return {{"c1-quadratic", Method::C1Quadratic, options},
          cloughTocher(CloughTocherVariant::AffineInvariant, storedGradients),
          cloughTocher(CloughTocherVariant::Book, storedGradients)};
}
// Every method but flat: linear, bilinear, quadratic and the C1 ones.
inline std::vector<MethodCase> allMethods(bool storedGradients = true) {
  std::vector<MethodCase> out = {
      {"gouraud", Method::Gouraud, {}}, {"bilinear", Method::Bilinear, {}}, {"quadratic", Method::Quadratic, {}}};
  for (const MethodCase& m : c1Methods(storedGradients)) out.push_back(m);
  return out;
}

// Every triangle cut into four at its edge midpoints (new nodes shared between neighbours,
// valued by f): the same triangle shapes at half the size, so a sequence of refinements
// measures a convergence order free of the noise of re-jittering. Triangle meshes only.
inline RadiosityMesh refined(const RadiosityMesh& mesh, const Field& f, const Plane& plane = {}) {
  RadiosityMesh out = mesh;
  out.elements.clear();
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
  auto midpoint = [&](uint32_t a, uint32_t b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = mid.find(key);
    if (it == mid.end()) {
      const Vec3 p = 0.5 * (out.nodes[a].position + out.nodes[b].position);
      it = mid.emplace(key, uint32_t(out.nodes.size())).first;
      out.nodes.push_back({p, f(plane.coords(p)), {}});
    }
    return it->second;
  };
  for (const Element& e : mesh.elements) {
    const uint32_t a = e.corners[0], b = e.corners[1], c = e.corners[2];
    const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    for (const std::array<uint32_t, 3>& t :
         {std::array<uint32_t, 3>{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}})
      out.elements.push_back(Element{{t[0], t[1], t[2]}, {}, e.material, e.surface});
  }
  return out;
}

// Exact surface gradient of a field: per channel, the 2D gradient in the plane's (x, y).
using GradientField = std::function<std::array<Vec2, 3>(const Vec2&)>;

// The world-space vector of a 2D gradient in the plane.
inline Vec3 worldGradient(const Vec2& g, const Plane& plane = {}) { return g.x * plane.u + g.y * plane.v; }

// Sets every node's B from f at its position.
inline void setValues(RadiosityMesh& mesh, const Field& f, const Plane& plane = {}) {
  for (Node& node : mesh.nodes) node.B = f(plane.coords(node.position));
}

// Stores the exact gradients of a field in the mesh (hasGradients = true).
inline void setGradients(RadiosityMesh& mesh, const GradientField& g, const Plane& plane = {}) {
  for (Node& node : mesh.nodes) {
    const std::array<Vec2, 3> g2 = g(plane.coords(node.position));
    for (int c = 0; c < 3; ++c) node.gradient[c] = worldGradient(g2[c], plane);
  }
  mesh.hasGradients = true;
}

// Longest edge over the height onto it: 2/sqrt(3) for an equilateral triangle, large for needles (one short edge) and
// caps (one vertex near the opposite edge) alike.
inline double aspectRatio(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
  const double twiceArea = glm::length(glm::cross(b - a, c - a));
  return twiceArea > 0.0 ? longest * longest / twiceArea : std::numeric_limits<double>::infinity();
}
inline double aspectRatio(const RadiosityMesh& mesh, size_t element) {
  const auto& c = mesh.elements[element].corners;
  return aspectRatio(mesh.nodes[c[0]].position, mesh.nodes[c[1]].position, mesh.nodes[c[2]].position);
}

// Signed area of a triangle element in the plane's (x, y): positive when counter-clockwise.
inline double signedArea(const RadiosityMesh& mesh, const Element& e, const Plane& plane = {}) {
  const Vec2 a = plane.coords(mesh.nodes[e.corners[0]].position), b = plane.coords(mesh.nodes[e.corners[1]].position),
             c = plane.coords(mesh.nodes[e.corners[2]].position);
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// A jittered triangle gridMesh in which a `fraction` of the interior nodes are then moved to
// make slivers of aspect ratio 10 .. maxAspect (log-uniform): half of them next to a
// neighbour (needles: the edges to it become short) and half next to the far edge of one of
// their triangles (caps). A move that would fold a triangle over (or make one thinner than
// maxAspect) is not made. Values from f at the final positions.
// Note the limits of the mesh layer (MeshTopology): nodes closer than 1e-7 of the mesh's
// diagonal are welded into one, and a node within 1e-5 of an edge's length of that edge is
// taken for a T-vertex of the element across it, so maxAspect should stay below ~1e4.
inline RadiosityMesh sliverMesh(int n, double maxAspect, double fraction, const Field& f, uint32_t seed,
                                const Plane& plane = {}) {
  RadiosityMesh mesh = gridMesh(n, false, 0.25, f, seed, plane);
  std::mt19937 random(seed * 7919u + 1u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::vector<uint32_t>> star(mesh.nodes.size());
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (uint32_t c : mesh.elements[e].corners) star[c].push_back(e);
  auto interior = [n](uint32_t node) {
    const int i = int(node % uint32_t(n + 1)), j = int(node / uint32_t(n + 1));
    return i > 0 && i < n && j > 0 && j < n;
  };
  for (uint32_t node = 0; node < mesh.nodes.size(); ++node) {
    if (!interior(node) || unit(random) >= fraction) continue;
    const double aspect = std::pow(10.0, 1.0 + unit(random) * (std::log10(maxAspect) - 1.0));
    const Element& e = mesh.elements[star[node][size_t(unit(random) * double(star[node].size()))]];
    size_t k = 0;
    while (e.corners[k] != node) ++k;
    const Vec3 p = mesh.nodes[node].position;
    const Vec3 R = mesh.nodes[e.corners[(k + 1) % 3]].position, S = mesh.nodes[e.corners[(k + 2) % 3]].position;
    Vec3 moved;
    if (unit(random) < 0.5) {  // needle: next to R
      moved = R + (p - R) * (1.0 / aspect);
    } else {  // cap: at height |RS| / aspect above a point M of the edge R S
      const Vec3 M = R + (0.3 + 0.4 * unit(random)) * (S - R);
      const Vec3 along = (S - R) / glm::length(S - R);
      const double height = glm::length((p - M) - glm::dot(p - M, along) * along);
      moved = M + (p - M) * (glm::length(S - R) / aspect / height);
    }
    mesh.nodes[node].position = moved;
    bool valid = true;
    for (uint32_t t : star[node]) {
      const Element& s = mesh.elements[t];
      valid &= signedArea(mesh, s, plane) > 0.0 && aspectRatio(mesh, t) <= 2.0 * maxAspect;
    }
    if (!valid) mesh.nodes[node].position = p;
  }
  setValues(mesh, f, plane);
  return mesh;
}

// Points of a triangle, uniformly at random, as barycentric coordinates.
inline Vec3 randomBarycentric(std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r1 = std::sqrt(unit(random)), r2 = unit(random);
  return {1.0 - r1, r1 * (1.0 - r2), r1 * r2};
}

// Tags every element edge whose two ends satisfy `onLine` (in the plane's (x, y)) with `order`.
inline void tagEdges(RadiosityMesh& mesh, const std::function<bool(const Vec2&, const Vec2&)>& onLine, Continuity order,
                     const Plane& plane = {}) {
  std::set<std::pair<uint32_t, uint32_t>> done;
  for (const Element& e : mesh.elements)
    for (size_t k = 0; k < e.corners.size(); ++k) {
      const uint32_t a = e.corners[k], b = e.corners[(k + 1) % e.corners.size()];
      if (!onLine(plane.coords(mesh.nodes[a].position), plane.coords(mesh.nodes[b].position))) continue;
      if (done.insert({std::min(a, b), std::max(a, b)}).second) mesh.discontinuities.push_back({a, b, order});
    }
}

// Moves the grid column i (x) and row j (y) of a gridMesh(n, ...) onto the lines x = i / n
// and y = j / n exactly (in the plane's coordinates, up to the rounding of Plane::at); -1 for
// none. Jitter below half a cell keeps every element valid.
inline void straightenGridLines(RadiosityMesh& mesh, int n, int column, int row, const Plane& plane = {}) {
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      Node& node = mesh.nodes[size_t(j * (n + 1) + i)];
      Vec2 p = plane.coords(node.position);
      if (i == column) p.x = double(column) / n;
      if (j == row) p.y = double(row) / n;
      node.position = plane.at(p.x, p.y);
    }
}

// Cuts the mesh along the line x = x0 (plane coordinates, within 1e-9): every node on it used
// by an element on the x > x0 side gets a twin at the same position for that side, and the
// line's edges are tagged C-1. Returns, for each node on the line, its twin's index.
inline std::map<uint32_t, uint32_t> cutAlongLine(RadiosityMesh& mesh, double x0, const Plane& plane = {}) {
  auto on = [&](uint32_t node) { return std::abs(plane.coords(mesh.nodes[node].position).x - x0) < 1e-9; };
  std::map<uint32_t, uint32_t> twin;
  for (Element& e : mesh.elements) {
    Vec3 centre(0.0);
    for (uint32_t c : e.corners) centre += mesh.nodes[c].position;
    if (plane.coords(centre / double(e.corners.size())).x < x0) continue;
    for (auto* list : {&e.corners, &e.midEdge})
      for (uint32_t& node : *list) {
        if (!on(node)) continue;
        auto it = twin.find(node);
        if (it == twin.end()) {
          it = twin.emplace(node, uint32_t(mesh.nodes.size())).first;
          mesh.nodes.push_back(mesh.nodes[node]);
        }
        node = it->second;
      }
  }
  tagEdges(
      mesh, [&](const Vec2& a, const Vec2& b) { return std::abs(a.x - x0) < 1e-9 && std::abs(b.x - x0) < 1e-9; },
      Continuity::Cm1, plane);
  return twin;
}

// A random point of an element: uniform in a random triangle of the fan from corner 0.
inline Vec3 randomPointIn(const RadiosityMesh& mesh, uint32_t element, std::mt19937& random) {
  const auto& c = mesh.elements[element].corners;
  const size_t fan = c.size() == 3 ? 1 : 1 + size_t(random() % (c.size() - 2));
  const Vec3 w = randomBarycentric(random);
  return w.x * mesh.nodes[c[0]].position + w.y * mesh.nodes[c[fan]].position + w.z * mesh.nodes[c[fan + 1]].position;
}

// Twice the area over the longest edge (a triangle's smallest height), and the longest edge
// over that: the element's size across and its aspect ratio, for polygons too.
inline double elementHeight(const RadiosityMesh& mesh, uint32_t element) {
  const auto p = mesh.cornerPositions(element);
  double longest = 0.0;
  Vec3 twiceArea(0.0);
  for (size_t i = 0; i < p.size(); ++i) {
    longest = std::max(longest, glm::length(p[(i + 1) % p.size()] - p[i]));
    twiceArea += glm::cross(p[i] - p[0], p[(i + 1) % p.size()] - p[0]);
  }
  return longest > 0.0 ? glm::length(twiceArea) / longest : 0.0;
}
inline double elementAspect(const RadiosityMesh& mesh, uint32_t element) {
  const auto p = mesh.cornerPositions(element);
  double longest = 0.0;
  for (size_t i = 0; i < p.size(); ++i) longest = std::max(longest, glm::length(p[(i + 1) % p.size()] - p[i]));
  const double h = elementHeight(mesh, element);
  return h > 0.0 ? longest / h : std::numeric_limits<double>::infinity();
}

// Per element, the largest aspect ratio and the smallest height among the elements that
// share a node position with it (itself included): what round-off in anything built from
// the vertex neighbourhoods (estimated gradients, Powell-Sabin split points) scales with.
struct Neighbourhood {
  double aspect = 1.0, height = std::numeric_limits<double>::infinity();
};
inline std::vector<Neighbourhood> neighbourhoods(const RadiosityMesh& mesh) {
  const MeshTopology topology(mesh);
  std::vector<Neighbourhood> atPosition(topology.positionCount());
  auto nodesOf = [&](uint32_t e) {
    std::vector<uint32_t> nodes = mesh.elements[e].corners;
    nodes.insert(nodes.end(), mesh.elements[e].midEdge.begin(), mesh.elements[e].midEdge.end());
    return nodes;
  };
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (uint32_t n : nodesOf(e)) {
      Neighbourhood& at = atPosition[topology.positionId(n)];
      at.aspect = std::max(at.aspect, elementAspect(mesh, e));
      at.height = std::min(at.height, elementHeight(mesh, e));
    }
  std::vector<Neighbourhood> out(mesh.elements.size());
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (uint32_t n : nodesOf(e)) {
      const Neighbourhood& at = atPosition[topology.positionId(n)];
      out[e].aspect = std::max(out[e].aspect, at.aspect);
      out[e].height = std::min(out[e].height, at.height);
    }
  return out;
}

// An interior element edge: the two elements that share it, its ends (as element `first`
// runs it) and its tagged continuity.
struct InteriorEdge {
  uint32_t first = 0, second = 0;
  Vec3 a{0.0}, b{0.0};
  Continuity continuity = Continuity::C1;
};
inline std::vector<InteriorEdge> interiorEdges(const RadiosityMesh& mesh) {
  const MeshTopology topology(mesh);
  std::vector<InteriorEdge> out;
  for (const MeshEdge& edge : topology.edges()) {
    if (topology.sides(edge).size() != 2) continue;
    const Element& e = mesh.elements[topology.sides(edge)[0].element];
    const uint32_t k = topology.sides(edge)[0].edge;
    out.push_back({topology.sides(edge)[0].element, topology.sides(edge)[1].element, mesh.nodes[e.corners[k]].position,
                   mesh.nodes[e.corners[(k + 1) % e.corners.size()]].position, edge.continuity});
  }
  return out;
}

// The largest |B| (any channel) over the nodes of the given elements.
inline double maxAbsB(const RadiosityMesh& mesh, std::initializer_list<uint32_t> elements) {
  double out = 0.0;
  for (uint32_t e : elements)
    for (const auto* list : {&mesh.elements[e].corners, &mesh.elements[e].midEdge})
      for (uint32_t n : *list)
        out = std::max({out, std::abs(mesh.nodes[n].B.x), std::abs(mesh.nodes[n].B.y), std::abs(mesh.nodes[n].B.z)});
  return out;
}

// An element with its nodes, for failure messages: the failing input, printed.
inline std::string describe(const RadiosityMesh& mesh, uint32_t element) {
  std::ostringstream os;
  os.precision(17);
  os << "element " << element << ' ' << mesh.elements[element] << " aspect " << elementAspect(mesh, element) << ':';
  for (const auto* list : {&mesh.elements[element].corners, &mesh.elements[element].midEdge})
    for (uint32_t n : *list) os << "\n    node " << n << ' ' << mesh.nodes[n];
  return os.str();
}

// The observed order of convergence: the least-squares slope of log(error) against log(n), n
// the cells per side of each mesh (the element size is 1/n), over the pairs given.
inline double observedOrder(const std::vector<int>& cells, const std::vector<double>& errors) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double count = double(cells.size());
  for (size_t i = 0; i < cells.size(); ++i) {
    const double x = std::log(double(cells[i])), y = -std::log(errors[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (count * sxy - sx * sy) / (count * sxx - sx * sx);
}

}  // namespace radview::test
