#pragma once
// Scenes at numerical extremes (issue 7), shared by the GL tests (tests/gl/extremes_render_test.cpp)
// and the final gather's (tests/gather/extremes_gather_test.cpp): a closed box of many elements
// with T-vertices, slivers and mixed quads and triangles, placed at any scale and distance from
// the origin, with radiosities spanning 1e-8..1e8; and cameras inside it.
#include "core/camera.h"
#include "mesh/radiosity_mesh.h"

#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace radview::test {

// Where the unit box [0, 1]^3 goes: x -> origin + scale (x - 0.5).
struct Placement {
  std::string name;
  double scale = 1.0;
  Vec3 origin{0.0};
  Vec3 place(const Vec3& unit) const { return origin + scale * (unit - Vec3(0.5)); }
};

inline std::vector<Placement> extremePlacements() {
  return {{"unit", 1.0, Vec3(0.0)},
          {"scale 1e-6", 1e-6, Vec3(0.0)},
          {"scale 1e6", 1e6, Vec3(0.0)},
          {"at 1e5", 1.0, Vec3(1e5, -1e5, 1e5)},
          // float32 resolves 0.0078 at 1e5: the whole box is an eighth of that.
          {"scale 1e-3 at 1e5", 1e-3, Vec3(1e5, -1e5, 1e5)}};
}

// Grid lines across each face, in the face's own (u, v) in [0, 1]: eighths, plus a line 1.25e-5
// beside u = 1/4 (a column of slivers an eighth long: aspect 1e4) and one 1e-6 beside u = 3/4
// (a sliver the face's length: aspect 1e6).
inline const std::vector<double>& extremeGridU() {
  static const std::vector<double> u = {0, 0.125, 0.25, 0.25 + 1.25e-5, 0.375, 0.5, 0.625, 0.75, 0.75 + 1e-6, 0.875, 1};
  return u;
}

// Radiosity at a point of the unit box: 10^(-8 + 16 (x + y + z) / 3), 1e-8 at the corner (0,0,0)
// and 1e8 at (1,1,1), a factor of about 20 between the corners of a cell. Grey, so that any
// colour in a displayed normal view is garbage.
inline double extremeRadiosity(const Vec3& unit) {
  return std::pow(10.0, -8.0 + 16.0 * (unit.x + unit.y + unit.z) / 3.0);
}

// The closed box, each face facing inwards and cut along extremeGridU() by eighths: cells split
// in four (leaving T-vertices on their unsplit neighbours' edges, some on the aspect-1e4
// slivers), cells cut into two triangles, quads; the short slivers alternate quads and triangle
// pairs. The aspect-1e6 sliver and the columns beside it are single elements the face's length:
// MeshTopology welds nodes within 1e-7 of the diagonal and counts a node within 1e-5 of an edge's
// length as on it, so a shorter one would be welded shut, and a neighbour's node beside it would
// be taken for a T-vertex of its far edge. With `emitter`, the
// top face (y = 1) emits E = 1 (rho 0) and the rest reflects 0.5, for the final gather.
inline RadiosityMesh extremeBox(const Placement& placement, bool emitter = false) {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"wall", Rgb(0.5), Rgb(0.0)});
  mesh.materials.push_back(Material{"light", Rgb(0.0), Rgb(emitter ? 1.0 : 0.0)});
  // One node per point of the unit box; points are exact sums of exactly representable terms, so
  // the faces meeting at a box edge name the same points.
  std::map<std::tuple<double, double, double>, uint32_t> nodeAt;
  auto node = [&](const Vec3& unit) {
    const auto key = std::make_tuple(unit.x, unit.y, unit.z);
    auto it = nodeAt.find(key);
    if (it != nodeAt.end()) return it->second;
    const uint32_t index = uint32_t(mesh.nodes.size());
    mesh.nodes.push_back({placement.place(unit), Rgb(extremeRadiosity(unit)), {}});
    nodeAt.emplace(key, index);
    return index;
  };
  struct Face {
    Vec3 corner, U, V;  // points corner + u U + v V; U x V is the inward normal
  };
  const Face faces[6] = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}},
                         {{0, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                         {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}}};
  const std::vector<double>& U = extremeGridU();
  for (int f = 0; f < 6; ++f) {
    const Face& face = faces[f];
    const int material = f == 5 ? 1 : 0;
    auto at = [&](double u, double v) { return node(face.corner + u * face.U + v * face.V); };
    auto quad = [&](double u0, double u1, double v0, double v1) {
      mesh.elements.push_back(Element{{at(u0, v0), at(u1, v0), at(u1, v1), at(u0, v1)}, {}, material, f});
    };
    auto triangles = [&](double u0, double u1, double v0, double v1) {
      mesh.elements.push_back(Element{{at(u0, v0), at(u1, v0), at(u1, v1)}, {}, material, f});
      mesh.elements.push_back(Element{{at(u0, v0), at(u1, v1), at(u0, v1)}, {}, material, f});
    };
    for (size_t i = 0; i + 1 < U.size(); ++i)
      for (int j = 0; j < 8; ++j) {
        const double u0 = U[i], u1 = U[i + 1], v0 = j / 8.0, v1 = (j + 1) / 8.0;
        const bool sliver = u1 - u0 < 1e-3;
        if (i >= 6 && i <= 8) {
          if (j == 0 && i == 7) triangles(u0, u1, 0.0, 1.0);
          if (j == 0 && i != 7) quad(u0, u1, 0.0, 1.0);
        } else if (sliver) {
          if (j % 2)
            triangles(u0, u1, v0, v1);
          else
            quad(u0, u1, v0, v1);
        } else if ((i + j + size_t(f)) % 3 == 0) {
          const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
          quad(u0, um, v0, vm);
          quad(um, u1, v0, vm);
          quad(um, u1, vm, v1);
          quad(u0, um, vm, v1);
        } else if ((i + 2 * size_t(j) + size_t(f)) % 5 == 0) {
          triangles(u0, u1, v0, v1);
        } else {
          quad(u0, u1, v0, v1);
        }
      }
  }
  return mesh;
}

// A camera inside the box, given in the unit box's coordinates and placed with the box; its clip
// planes fitted to the box's bounds as `radview render` fits them.
inline Camera extremeCamera(const Placement& placement, const Vec3& eye, const Vec3& target,
                            const Vec3& up = Vec3(0, 1, 0), double yfovDegrees = 60.0) {
  Camera camera;
  camera.eye = placement.place(eye);
  camera.target = placement.place(target);
  camera.up = up;
  camera.yfov = yfovDegrees * M_PI / 180.0;
  Bounds bounds;
  bounds.extend(placement.place(Vec3(0.0)));
  bounds.extend(placement.place(Vec3(1.0)));
  fitClipPlanes(camera, bounds);
  return camera;
}

struct NamedView {
  std::string name;
  Vec3 eye, target, up;
};

// Views from inside the box (unit coordinates): into a corner; along the floor (z = 0) 1e-3 above
// it and 0.01 degree from edge-on; 1e-5 from a wall looking along it; 1e-5 from a wall looking at
// it; and along a column of slivers on the floor, 0.01 degree from edge-on.
inline std::vector<NamedView> insideViews() {
  const double grazing = std::tan(0.01 * M_PI / 180.0);
  return {{"into a corner", {0.3, 0.4, 0.35}, {0.9, 0.8, 0.95}, {0, 1, 0}},
          {"grazing the floor", {0.5, 0.02, 1e-3}, {0.5, 1.02, 1e-3 - grazing}, {0, 0, 1}},
          {"1e-5 from a wall, along it", {0.5, 0.5, 1.0 - 1e-5}, {0.5, 0.9, 1.0 - 1e-5}, {1, 0, 0}},
          {"1e-5 from a wall, at it", {0.4, 0.6, 1e-5}, {0.4, 0.6, 0.0}, {0, 1, 0}},
          {"grazing the slivers", {0.75 + 5e-7, 0.02, 2e-3}, {0.75 + 5e-7, 1.02, 2e-3 - grazing}, {0, 0, 1}}};
}

}  // namespace radview::test
