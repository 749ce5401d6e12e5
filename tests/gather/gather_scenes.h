#pragma once
// Scenes for the final gather's tests, each with an answer known in closed form.
#include "mesh/radiosity_mesh.h"
#include "mesh/uniform_mesher.h"
#include "scene/scene.h"

namespace radview::test {

// A 4 x 4 receiver (rho 0.5) at z = 0 facing +z, under a unit square emitter at z = 1 facing
// it (E 1, rho 0): the receiver's radiosity is rho E F(x -> emitter), nothing else.
inline Scene receiverUnderSquareEmitter() {
  Scene scene;
  scene.materials = {{"receiver", {0.5, 0.5, 0.5}, {0, 0, 0}}, {"emitter", {0, 0, 0}, {1, 1, 1}}};
  scene.polygons.push_back({{{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}}, 0});
  scene.polygons.push_back({{{-0.5, -0.5, 1}, {-0.5, 0.5, 1}, {0.5, 0.5, 1}, {0.5, -0.5, 1}}, 1});
  return scene;
}

// The scene meshed with its exact solution where eq. 9.9 needs one: B^ = E on the emitter (it
// reflects nothing), which the receiver's indirect rays meet as B^ - E = 0.
inline RadiosityMesh receiverUnderSquareEmitterMesh() {
  const Scene scene = receiverUnderSquareEmitter();
  RadiosityMesh mesh = meshUniformly(scene, 0.5);
  for (const Element& e : mesh.elements)
    for (uint32_t n : e.corners) mesh.nodes[n].B = mesh.materials[size_t(e.material)].E;
  return mesh;
}

}  // namespace radview::test
