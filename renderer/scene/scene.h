#pragma once
// The scene model: diffuse (Lambertian) planar polygons with a reflectance rho and an
// emission E, in world space. Nothing else: radiosity needs no more (C&W ch. 2).
#include "core/types.h"

#include <ostream>
#include <string>
#include <vector>

namespace radview {

struct Material {
  std::string name;
  Rgb rho{0.0};  // diffuse reflectance per channel, in [0,1]
  Rgb E{0.0};    // emitted radiosity (exitance), same unit as B
  bool isEmitter() const { return E.r > 0.0 || E.g > 0.0 || E.b > 0.0; }
};

// A planar polygon, convex or concave, vertices in counter-clockwise order seen from the
// side it faces (its normal by the right-hand rule). Emitters emit on that side only.
struct Polygon {
  std::vector<Vec3> vertices;
  int material = 0;
};

struct SceneCamera {
  std::string name;
  Vec3 eye{0.0, 0.0, 1.0};
  Vec3 target{0.0};
  Vec3 up{0.0, 1.0, 0.0};
  double yfov = glm::radians(45.0);  // full vertical field of view, radians
};

struct Scene {
  std::vector<Polygon> polygons;
  std::vector<Material> materials;
  std::vector<SceneCamera> cameras;  // from the file, in file order

  Bounds bounds() const;
  // Indices of polygons whose material emits.
  std::vector<int> emitters() const;
};

std::ostream& operator<<(std::ostream& os, const Material& m);

}  // namespace radview
