#pragma once
// The view the GL tests draw the unit-square scenes from (assets/discontinuities.gltf, the
// fig. 9.8 quad): from the front and above, obliquely, so that perspective, silhouettes and
// depth all play a part.
#include "core/camera.h"

namespace radview::test {

inline Camera obliqueView() {
  Camera camera;
  camera.eye = {0.5, -0.6, 1.1};
  camera.target = {0.5, 0.5, 0.0};
  camera.zNear = 0.1;
  camera.zFar = 10.0;
  return camera;
}

}  // namespace radview::test
