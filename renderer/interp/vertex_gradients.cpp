#include "interp/vertex_gradients.h"

#include "core/disjoint_sets.h"
#include "core/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

namespace radview {

namespace {

using Gradient = std::array<Vec3, 3>;  // per channel

// Two unit vectors spanning the plane with unit normal n.
std::pair<Vec3, Vec3> planeBasis(const Vec3& n) {
  const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 u = glm::normalize(glm::cross(n, helper));
  return {u, glm::cross(n, u)};
}

// Minimum-norm solution of the 2x2 symmetric system M g = r (per channel), treating
// eigenvalues below 1e-12 of the largest as zero: a rank-deficient stencil fixes only the
// components it sees.
std::array<Vec2, 3> solveSymmetric2(double a, double b, double d, const std::array<Vec2, 3>& r) {
  std::array<Vec2, 3> out{};
  // The half-difference of the eigenvalues as hypot((a - d) / 2, b), not from trace^2 / 4 - det,
  // which cancels to an absolute error of eps * trace.
  const double trace = a + d;
  const double disc = std::hypot(0.5 * (a - d), b);
  const double l1 = 0.5 * trace + disc, l2 = 0.5 * trace - disc;  // l1 >= l2 >= 0
  if (!(l1 > 0.0)) return out;
  // Eigenvector of l1, from the row of M - l1 I without cancellation: (l1 - d, b) when a >= d,
  // else (b, l1 - a). When a < d and b is small, l1 - d is a tiny difference whose rounding
  // turns (l1 - d, b) away from the eigenvector: gradients of exactly linear data would be off
  // by 1e-8 on a regular, symmetric stencil (extremes_test, the needle-row mesh).
  Vec2 e1 = std::abs(b) > 1e-300 ? (a >= d ? Vec2(l1 - d, b) : Vec2(b, l1 - a)) : (a >= d ? Vec2(1, 0) : Vec2(0, 1));
  e1 = glm::normalize(e1);
  const Vec2 e2(-e1.y, e1.x);
  for (int c = 0; c < 3; ++c) {
    Vec2 g = glm::dot(e1, r[c]) / l1 * e1;
    if (l2 > 1e-12 * l1) g += glm::dot(e2, r[c]) / l2 * e2;
    out[c] = g;
  }
  return out;
}

// The least-squares plane through (x0, f0) and the given neighbours, in the plane of n.
Gradient leastSquaresGradient(const Vec3& x0, const Rgb& f0, const std::vector<std::pair<Vec3, Rgb>>& neighbours,
                              const Vec3& n) {
  const auto [u, v] = planeBasis(n);
  // Scale the stencil to unit size so the rank threshold is relative to geometry, not units.
  double scale = 0.0;
  for (const auto& [x, f] : neighbours) scale = std::max(scale, glm::length(x - x0));
  Gradient g{};
  if (!(scale > 0.0)) return g;
  double a = 0, b = 0, d = 0;
  std::array<Vec2, 3> r{};
  for (const auto& [x, f] : neighbours) {
    const Vec2 p(glm::dot(x - x0, u) / scale, glm::dot(x - x0, v) / scale);
    a += p.x * p.x;
    b += p.x * p.y;
    d += p.y * p.y;
    for (int c = 0; c < 3; ++c) r[c] += p * (f[c] - f0[c]);
  }
  const std::array<Vec2, 3> g2 = solveSymmetric2(a, b, d, r);
  for (int c = 0; c < 3; ++c) g[c] = (g2[c].x * u + g2[c].y * v) / scale;
  return g;
}

// Gradient of the element's quadratic at corner k from the parabolas along its two edges at
// that corner (fig. 9.10): slope along an edge from f(0), f(1/2), f(1): -3 f0 + 4 fm - f1.
Gradient parabolaGradient(const RadiosityMesh& mesh, const Element& e, size_t k, const Vec3& n) {
  const size_t count = e.corners.size();
  const Vec3 x0 = mesh.nodes[e.corners[k]].position;
  const Rgb f0 = mesh.nodes[e.corners[k]].B;
  const size_t next = (k + 1) % count, previous = (k + count - 1) % count;
  const Vec3 t1 = mesh.nodes[e.corners[next]].position - x0;
  const Vec3 t2 = mesh.nodes[e.corners[previous]].position - x0;
  const Rgb s1 = -3.0 * f0 + 4.0 * mesh.nodes[e.midEdge[k]].B - mesh.nodes[e.corners[next]].B;
  const Rgb s2 = -3.0 * f0 + 4.0 * mesh.nodes[e.midEdge[previous]].B - mesh.nodes[e.corners[previous]].B;
  // g . t1 = s1, g . t2 = s2, g in the plane: a least-squares solve handles collinear edges.
  return leastSquaresGradient(x0, f0, {{x0 + t1, f0 + s1}, {x0 + t2, f0 + s2}}, n);
}

Vec3 project(const Vec3& g, const Vec3& n) { return g - glm::dot(g, n) * n; }

}  // namespace

CornerGradients vertexGradients(const SurfaceTriangulation& surface, bool useStored) {
  const RadiosityMesh& mesh = surface.mesh();
  const auto& triangles = surface.triangles();
  if (useStored && mesh.hasGradients) {
    // Projected into each triangle's plane: a gradient per corner.
    std::vector<uint32_t> corner(3 * triangles.size());
    std::iota(corner.begin(), corner.end(), 0u);
    std::vector<Gradient> projected(corner.size());
    for (uint32_t t = 0; t < triangles.size(); ++t) {
      const Vec3 n = surface.normal(t);
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) projected[3 * t + k][c] = project(mesh.nodes[triangles[t].node[k]].gradient[c], n);
    }
    return CornerGradients(std::move(corner), std::move(projected));
  }

  // Sectors: corners at one vertex joined across C1 edges.
  DisjointSets<uint32_t> sectors(3 * triangles.size());  // over triangle corners (3 t + k)
  for (uint32_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int64_t u = triangles[t].neighbour[k];
      if (u < 0 || triangles[t].continuity[k] != Continuity::C1) continue;
      for (int end = 0; end < 2; ++end) {
        const int corner = (k + end) % 3;
        const int other = surface.cornerAt(uint32_t(u), triangles[t].node[corner]);
        if (other >= 0) sectors.join(3 * t + corner, 3 * uint32_t(u) + other);
      }
    }
  // Each sector's corners, in increasing corner order, as lists in one array (counting sort):
  // sector s holds members[first[s] .. first[s + 1]); sectorOf[c] is corner c's. Sectors are
  // numbered in the order of their roots.
  const uint32_t cornerCount = uint32_t(3 * triangles.size());
  std::vector<uint32_t> sectorOf(cornerCount), sectorOfRoot(cornerCount, UINT32_MAX);
  for (uint32_t c = 0; c < cornerCount; ++c) sectorOfRoot[sectors.find(c)] = 0;
  uint32_t sectorCount = 0;
  for (uint32_t& s : sectorOfRoot)
    if (s == 0) s = sectorCount++;
  std::vector<uint32_t> first(sectorCount + 1, 0), members(cornerCount);
  for (uint32_t c = 0; c < cornerCount; ++c) ++first[(sectorOf[c] = sectorOfRoot[sectors.find(c)]) + 1];
  std::vector<uint32_t>().swap(sectorOfRoot);
  std::partial_sum(first.begin(), first.end(), first.begin());
  {
    std::vector<uint32_t> next(first.begin(), first.end() - 1);
    for (uint32_t c = 0; c < cornerCount; ++c) members[next[sectorOf[c]]++] = c;
  }

  // Each sector's gradient, independent of the others': on every core.
  std::vector<Gradient> sectorGradient(sectorCount);
  parallelFor(sectorCount, [&](size_t s) {
    const uint32_t* corners = &members[first[s]];
    const size_t count = first[s + 1] - first[s];
    const uint32_t t0 = corners[0] / 3;
    const uint32_t node = triangles[t0].node[corners[0] % 3];
    // The sector's plane from a triangle that has one: a zero-area triangle (validateMesh
    // refuses them, but a mesh built in code can hold one) has a zero normal, and the plane
    // basis and least-squares gradient built on it were NaN (two coincident nodes made the
    // C1 interpolants abort in buildPowellSabin / buildCloughTocher). No plane at all: 0.
    Vec3 n(0.0);
    for (size_t i = 0; i < count && n == Vec3(0.0); ++i) n = surface.normal(corners[i] / 3);
    if (n == Vec3(0.0)) {
      sectorGradient[s] = Gradient{};
      return;
    }
    const Vec3 x0 = mesh.nodes[node].position;
    // The sector's elements, in increasing order (the sum below adds them in that order).
    std::vector<uint32_t> elements;
    for (size_t i = 0; i < count; ++i) elements.push_back(triangles[corners[i] / 3].element);
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
    bool allQuadratic = true;
    for (uint32_t e : elements) allQuadratic &= mesh.elements[e].order() == ElementOrder::Quadratic;
    Gradient g{};
    if (allQuadratic) {
      int used = 0;
      for (uint32_t e : elements) {
        const Element& element = mesh.elements[e];
        for (size_t k = 0; k < element.corners.size(); ++k)
          if (element.corners[k] == node) {
            const Gradient ge = parabolaGradient(mesh, element, k, n);
            for (int c = 0; c < 3; ++c) g[c] += ge[c];
            ++used;
          }
      }
      for (int c = 0; c < 3; ++c) g[c] /= std::max(used, 1);
    } else {
      // The other nodes of the sector's triangles, each once, in the order first met.
      std::vector<uint32_t> seen{node};
      std::vector<std::pair<Vec3, Rgb>> neighbours;
      for (size_t i = 0; i < count; ++i)
        for (uint32_t m : triangles[corners[i] / 3].node)
          if (std::find(seen.begin(), seen.end(), m) == seen.end()) {
            seen.push_back(m);
            neighbours.push_back({mesh.nodes[m].position, mesh.nodes[m].B});
          }
      g = leastSquaresGradient(x0, mesh.nodes[node].B, neighbours, n);
    }
    sectorGradient[s] = g;
  });

  // C0 edges: the sectors on either side agree along the edge.
  struct Constraint {
    Vec3 t;  // unit edge direction
    Rgb slope;
  };
  std::map<uint32_t, std::vector<Constraint>> constraints;
  // Each C0 edge end is met twice, once from either side: one constraint per (sector, sector,
  // far end of the edge). Keyed by the sector pair alone, the second of two C0 edges that
  // separate the same two sectors (the corner of an L of C0 edges, where one sector lies
  // inside the L and one outside) was dropped, and B jumped along it (c1_mesh_test).
  std::set<std::tuple<uint32_t, uint32_t, uint32_t>> done;
  for (uint32_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int64_t u = triangles[t].neighbour[k];
      if (u < 0 || triangles[t].continuity[k] != Continuity::C0) continue;
      const auto p = surface.positions(t);
      // A zero-length edge (coincident nodes, in a mesh built in code) has no direction.
      if (p[(k + 1) % 3] == p[k]) continue;
      const Vec3 edge = glm::normalize(p[(k + 1) % 3] - p[k]);
      for (int end = 0; end < 2; ++end) {
        const int corner = (k + end) % 3;
        const int other = surface.cornerAt(uint32_t(u), triangles[t].node[corner]);
        if (other < 0) continue;
        const uint32_t a = sectorOf[3 * t + corner], b = sectorOf[3 * uint32_t(u) + other];
        const uint32_t far = surface.topology().positionId(triangles[t].node[(k + 1 - end) % 3]);
        if (a == b || !done.insert({std::min(a, b), std::max(a, b), far}).second) continue;
        Rgb slope;
        for (int c = 0; c < 3; ++c)
          slope[c] = 0.5 * (glm::dot(sectorGradient[a][c], edge) + glm::dot(sectorGradient[b][c], edge));
        constraints[a].push_back({edge, slope});
        constraints[b].push_back({edge, slope});
      }
    }
  for (auto& [sector, list] : constraints) {
    Gradient& g = sectorGradient[sector];
    const Constraint& first = list[0];
    // A second constraint along a different direction: both are met exactly (2 equations, 2
    // unknowns in the plane); along the same direction, it is the same constraint.
    const Constraint* second = nullptr;
    for (size_t i = 1; i < list.size() && !second; ++i)
      if (glm::length(glm::cross(list[i].t, first.t)) > 1e-6) second = &list[i];
    for (int c = 0; c < 3; ++c) {
      if (!second) {
        g[c] += (first.slope[c] - glm::dot(g[c], first.t)) * first.t;
        continue;
      }
      // g = alpha t1 + beta t2 + (the out-of-span part, zero in the plane).
      const double t12 = glm::dot(first.t, second->t);
      const double det = 1.0 - t12 * t12;
      const double alpha = (first.slope[c] - t12 * second->slope[c]) / det;
      const double beta = (second->slope[c] - t12 * first.slope[c]) / det;
      g[c] = alpha * first.t + beta * second->t;
    }
  }

  return CornerGradients(std::move(sectorOf), std::move(sectorGradient));
}

}  // namespace radview
