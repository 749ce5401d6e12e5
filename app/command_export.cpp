// radview export: a radiosity mesh out to PLY, so that other tools open radview's solutions,
// or to radview's own solution format, so that an imported mesh keeps its edits and tags.
#include "app/commands.h"
#include "app/solve_progress_bar.h"
#include "core/error.h"
#include "core/strings.h"
#include "import/ply_writer.h"
#include "mesh/solution_file.h"
#include "solve/viewed_file.h"

#include <iostream>

namespace radview {

int runExport(const ExportOptions& options) {
  const std::string ext = lowerExtension(options.out);
  if (ext != ".ply" && ext != ".glb" && ext != ".gltf")
    throw Error(options.out, "unknown output type \"" + ext + "\" (export writes .ply, .glb or .gltf)");
  const ViewedFile viewed = openForViewing(options.file, options.elementSize, options.import, options.light, nullptr,
                                           solveProgressOnTerminal(options.light));
  if (ext == ".ply")
    writePly(viewed.mesh, options.out);
  else
    writeSolution(viewed.mesh, options.out, viewed.file.scene.cameras);
  std::cout << options.out << ": " << viewed.mesh.nodes.size() << " nodes, " << viewed.mesh.elements.size()
            << " elements, " << viewed.mesh.discontinuities.size() << " discontinuity edges\n";
  if (!viewed.lighting.empty()) std::cout << "scene lighting: " << viewed.lighting << "\n";
  return 0;
}

}  // namespace radview
