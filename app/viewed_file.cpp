#include "app/viewed_file.h"

#include "mesh/topology.h"
#include "solve/direct_light.h"

namespace radview {

ViewedFile openForViewing(const std::string& path, double elementSize) {
  ViewedFile viewed;
  viewed.file = loadFile(path);
  if (viewed.file.isSolution) {
    viewed.mesh = viewed.file.mesh;
  } else {
    viewed.elementSize = elementSize > 0.0 ? elementSize : defaultElementSize(viewed.file.scene);
    viewed.mesh = meshAndLight(viewed.file.scene, viewed.elementSize);
  }
  viewed.tVertexCount = MeshTopology(viewed.mesh).tVertices().size();
  return viewed;
}

}  // namespace radview
