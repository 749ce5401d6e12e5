#pragma once
// What each pixel of a view sees of a radiosity mesh: the mesh's elements as ray-casting
// geometry, and the element at every pixel centre.
#include "core/camera.h"
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace radview {

// The elements as the ray caster's polygons, in element order (polygon i is element i): they
// tile the surfaces exactly, T-vertices included (a T-vertex lies on its neighbour's edge), so
// rays see no cracks.
Scene elementScene(const RadiosityMesh& mesh);

// The element seen through the centre of each pixel of a width x height view (row 0 the top
// row, the GL renderer's camera: CameraRays), or -1 where the eye ray meets nothing.
std::vector<int32_t> visibleElements(const RadiosityMesh& mesh, const Camera& camera, int width, int height);

}  // namespace radview
