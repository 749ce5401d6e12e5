#pragma once
// Meshes for the interpolant tests: planar triangle and quad meshes lying in an arbitrary
// plane in 3D (so nothing relies on z = 0), jittered, with values from a given function.
#include "mesh/radiosity_mesh.h"

#include <functional>
#include <map>
#include <random>

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
  auto id = [n](int i, int j) { return uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (quads) {
        mesh.elements.push_back(Element{{a, b, c, d}, {}, 0, 0});
      } else if (random() % 2) {
        mesh.elements.push_back(Element{{a, b, c}, {}, 0, 0});
        mesh.elements.push_back(Element{{a, c, d}, {}, 0, 0});
      } else {
        mesh.elements.push_back(Element{{a, b, d}, {}, 0, 0});
        mesh.elements.push_back(Element{{b, c, d}, {}, 0, 0});
      }
    }
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

}  // namespace radview::test
