#pragma once
// Scenes built in code for the solver's tests: a closed box (the furnace), the furnace with a
// block standing on its floor, and the Cornell box closed by a front wall (so that no light
// leaves it: emitted = absorbed + unshot).
#include "scene/scene.h"
#include "tests/solve/cornell_box.h"

#include <cmath>

namespace radview::test {

// The unit cube seen from inside: every face faces inward, all of one material.
inline Scene furnaceBox(const Rgb& rho, const Rgb& E) {
  Scene scene;
  scene.materials = {{"furnace", rho, E}};
  scene.polygons = {{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, 0},   // z = 0, faces +z
                    {{{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}}, 0},   // z = 1, faces -z
                    {{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, 0},   // x = 0, faces +x
                    {{{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}}, 0},   // x = 1, faces -x
                    {{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}, 0},   // y = 0, faces +y
                    {{{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}}, 0}};  // y = 1, faces -y
  return scene;
}

// furnaceBox with a block standing on its floor, of the same material: 0.4 x 0.3 x 0.4,
// centred, turned 20 degrees about the vertical so that its footprint crosses a uniform mesh's
// elements, its top and four sides facing out, open below (as the Cornell box's blocks). Every
// surface that can be seen still has B = E / (1 - rho); the floor under the block emits into
// it, and nothing of that leaves it.
inline Scene furnaceWithBlock(const Rgb& rho, const Rgb& E) {
  Scene scene = furnaceBox(rho, E);
  const double c = std::cos(0.349), s = std::sin(0.349), a = 0.2, h = 0.3;
  auto at = [&](double u, double y, double w) { return Vec3(0.5 + c * u - s * w, y, 0.5 + s * u + c * w); };
  const Vec3 b[4] = {at(-a, 0, -a), at(a, 0, -a), at(a, 0, a), at(-a, 0, a)};
  const Vec3 t[4] = {at(-a, h, -a), at(a, h, -a), at(a, h, a), at(-a, h, a)};
  scene.polygons.push_back({{t[0], t[3], t[2], t[1]}, 0});
  for (int i = 0; i < 4; ++i) scene.polygons.push_back({{b[i], t[i], t[(i + 1) % 4], b[(i + 1) % 4]}, 0});
  return scene;
}

// cornellBox() with a white front wall at z = 0, facing into the box.
inline Scene closedCornellBox() {
  Scene scene = cornellBox();
  scene.polygons.push_back({{{0, 0, 0}, {552.8, 0, 0}, {556, 548.8, 0}, {0, 548.8, 0}}, 0});
  return scene;
}

}  // namespace radview::test
