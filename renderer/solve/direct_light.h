#pragma once
// A first radiosity-like solution: the direct illumination of the scene's emitters at every
// node, exact for a scene where nothing occludes: C&W eq. 9.8 with E in place of B under the
// integral and V = 1.
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"

namespace radview {

// Sets every node's B = E + rho * sum over emitters e of E_e * F(node -> e), F the exact
// point-to-polygon form factor (pointToPolygonFormFactor), with no visibility. A node takes the
// surface normal (the scene polygon's, or the element's when it has no surface) and the
// material of the first element that uses it; an emitter does not light its own polygon.
// Nodes of no element keep their B. Runs on all cores.
void solveDirectIllumination(const Scene& scene, RadiosityMesh& mesh);

// meshUniformly(scene, elementSize), then solveDirectIllumination. Throws Error as
// meshUniformly does.
RadiosityMesh meshAndLight(const Scene& scene, double elementSize);

// The element size radview uses unless told otherwise: the scene's bounding diagonal / 40
// (the Cornell box: 24 mm, 5,150 elements); 1 for an empty or point-sized scene.
double defaultElementSize(const Scene& scene);

}  // namespace radview
