// Writes the mesh builder's seed corpus: each file named on the command line, opened as the
// viewer opens it (a solution as it is, a scene as a coarse mesh lit by its emitters), in the
// byte encoding of tests/fuzz/mesh_bytes.h.
//   radview_write_mesh_seeds OUT_DIR FILE...
#include "core/error.h"
#include "import/load_file.h"
#include "solve/direct_light.h"
#include "tests/fuzz/mesh_bytes.h"

#include <filesystem>
#include <fstream>
#include <iostream>

int main(int argc, char** argv) {
  using namespace radview;
  if (argc < 3) {
    std::cerr << "usage: " << argv[0] << " OUT_DIR FILE...\n";
    return 2;
  }
  const std::filesystem::path out = argv[1];
  try {
    std::filesystem::create_directories(out);
    for (int i = 2; i < argc; ++i) {
      const LoadedFile file = loadFile(argv[i]);
      // Coarse enough for the scenes to fit the encoding's 1024 elements.
      const RadiosityMesh mesh =
          file.isSolution ? file.mesh : meshAndLight(file.scene, glm::length(file.scene.bounds().extent()) / 6.0);
      const std::vector<uint8_t> bytes = fuzz::encodeMesh(mesh);
      const std::filesystem::path path = out / (std::filesystem::path(argv[i]).stem().string() + ".mesh");
      std::ofstream seed(path, std::ios::binary);
      seed.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
      if (!seed.flush()) throw Error(path.string(), "cannot write the seed");
      std::cout << path.string() << ": " << mesh.nodes.size() << " nodes, " << mesh.elements.size() << " elements\n";
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
  return 0;
}
