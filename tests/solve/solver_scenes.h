#pragma once
// Scenes built in code for the solver's tests: a closed box (the furnace) and the Cornell box
// closed by a front wall (so that no light leaves it: emitted = absorbed + unshot).
#include "scene/scene.h"
#include "tests/solve/cornell_box.h"

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

// cornellBox() with a white front wall at z = 0, facing into the box.
inline Scene closedCornellBox() {
  Scene scene = cornellBox();
  scene.polygons.push_back({{{0, 0, 0}, {552.8, 0, 0}, {556, 548.8, 0}, {0, 548.8, 0}}, 0});
  return scene;
}

}  // namespace radview::test
