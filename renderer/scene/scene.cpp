#include "scene/scene.h"

namespace radview {

Bounds Scene::bounds() const {
  Bounds b;
  for (const Polygon& p : polygons)
    for (const Vec3& v : p.vertices) b.extend(v);
  return b;
}

std::vector<int> Scene::emitters() const {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(polygons.size()); ++i)
    if (materials[polygons[i].material].isEmitter()) out.push_back(i);
  return out;
}

std::ostream& operator<<(std::ostream& os, const Material& m) {
  return os << "Material{" << m.name << " rho=" << m.rho << " E=" << m.E << '}';
}

}  // namespace radview
