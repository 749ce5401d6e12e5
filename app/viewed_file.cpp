#include "app/viewed_file.h"

#include "core/error.h"
#include "mesh/topology.h"
#include "solve/direct_light.h"

#include <string>

namespace radview {

ViewedFile openForViewing(const std::string& path, double elementSize, const ImportOptions& import) {
  ViewedFile viewed;
  viewed.file = loadFile(path, import);
  // Meshing, lighting and topology report problems without knowing the file: name it here,
  // so every error the user sees says which file it is about.
  try {
    if (viewed.file.isSolution) {
      viewed.mesh = std::move(viewed.file.mesh);  // one copy, not two
      viewed.file.mesh = {};
    } else {
      viewed.elementSize = elementSize > 0.0 ? elementSize : defaultElementSize(viewed.file.scene);
      viewed.mesh = meshAndLight(viewed.file.scene, viewed.elementSize);
    }
    viewed.tVertexCount = MeshTopology(viewed.mesh).tVertices().size();
  } catch (const Error& e) {
    const std::string what = e.what();
    throw what.rfind(path + ": ", 0) == 0 ? e : Error(path, what);
  }
  return viewed;
}

void checkFinalGatherRuns(const ViewedFile& viewed) {
  if (!viewed.file.gatherRefusal.empty())
    throw Error(viewed.file.path, "the final gather cannot run: " + viewed.file.gatherRefusal +
                                      "; the interpolants work on it (--method gouraud, clough-tocher, ...)");
}

}  // namespace radview
