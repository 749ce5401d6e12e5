#pragma once
// The measured Cornell box (../shared/corpus/cornell-box-data.md, section 4), in millimetres, as
// a test scene built in code so the tests do not depend on the glTF loader. Choices (the data
// leaves them open): the light is lowered 0.1 mm below the ceiling (the two are coplanar in the
// data), rho are the doc's band means, E is an arbitrary test value.
#include "scene/scene.h"

namespace radview::test {

inline Scene cornellBox() {
  Scene scene;
  // RGB: the band means listed blue, green, red in the data file, put in R, G, B order.
  scene.materials = {{"white", {0.734, 0.736, 0.698}, {0, 0, 0}},
                     {"red", {0.576, 0.083, 0.056}, {0, 0, 0}},
                     {"green", {0.133, 0.351, 0.114}, {0, 0, 0}},
                     {"light", {0.78, 0.78, 0.78}, {40, 30, 20}}};
  enum { white, red, green, light };
  auto quad = [&](int material, std::vector<Vec3> v) { scene.polygons.push_back({std::move(v), material}); };
  quad(white, {{552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2}});                  // floor
  quad(light, {{343, 548.7, 227}, {343, 548.7, 332}, {213, 548.7, 332}, {213, 548.7, 227}});  // light
  quad(white, {{556, 548.8, 0}, {556, 548.8, 559.2}, {0, 548.8, 559.2}, {0, 548.8, 0}});      // ceiling
  quad(white, {{549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556, 548.8, 559.2}});    // back wall
  quad(green, {{0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}});                  // right wall
  quad(red, {{552.8, 0, 0}, {549.6, 0, 559.2}, {556, 548.8, 559.2}, {556, 548.8, 0}});        // left wall
  const std::vector<std::vector<Vec3>> blocks = {// short block: top, then four sides
                                                 {{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}},
                                                 {{290, 0, 114}, {290, 165, 114}, {240, 165, 272}, {240, 0, 272}},
                                                 {{130, 0, 65}, {130, 165, 65}, {290, 165, 114}, {290, 0, 114}},
                                                 {{82, 0, 225}, {82, 165, 225}, {130, 165, 65}, {130, 0, 65}},
                                                 {{240, 0, 272}, {240, 165, 272}, {82, 165, 225}, {82, 0, 225}},
                                                 // tall block: top, then four sides
                                                 {{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}},
                                                 {{423, 0, 247}, {423, 330, 247}, {472, 330, 406}, {472, 0, 406}},
                                                 {{472, 0, 406}, {472, 330, 406}, {314, 330, 456}, {314, 0, 456}},
                                                 {{314, 0, 456}, {314, 330, 456}, {265, 330, 296}, {265, 0, 296}},
                                                 {{265, 0, 296}, {265, 330, 296}, {423, 330, 247}, {423, 0, 247}}};
  for (const auto& face : blocks) quad(white, face);
  return scene;
}

}  // namespace radview::test
