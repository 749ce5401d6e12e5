#include "import/gltf_colour_mesh.h"

#include "core/error.h"
#include "core/limits.h"
#include "scene/gltf_import.h"

#include <tiny_gltf.h>

#include <unordered_map>

namespace radview {

bool hasVertexColours(const GltfDocument& document) {
  for (const tinygltf::Mesh& mesh : document.model().meshes)
    for (const tinygltf::Primitive& primitive : mesh.primitives)
      if (primitive.attributes.count("COLOR_0")) return true;
  return false;
}

ColourMeshReading readColourMesh(const GltfDocument& document, const ImportOptions& options) {
  ColourMeshReading reading;
  ImportedMesh& imported = reading.imported;
  RadiosityMesh& mesh = imported.mesh;
  size_t withoutColours = 0;
  bool integerColours = false;
  auto addPrimitive = [&](const ImportedPrimitive& p) {
    const auto colour = p.primitive.attributes.find("COLOR_0");
    if (colour == p.primitive.attributes.end()) {
      ++withoutColours;
      return;
    }
    bool integer = false;
    const std::vector<Rgb> colours = readVertexColours(document, p.primitive, p.what, p.positions.size(), &integer);
    integerColours = integerColours || integer;
    // COLOR_0 is linear (glTF 2.0, "Meshes"): normalized integers are only scaled, never decoded,
    // unless --colours srgb says the file breaks that rule.
    const ColourEncoding encoding =
        options.colours == ColourEncoding::Srgb ? ColourEncoding::Srgb : ColourEncoding::Linear;
    // Only the vertices the triangles use become nodes: an instanced primitive with many unused
    // (or zero-filled) vertices must not multiply them.
    std::unordered_map<uint32_t, uint32_t> nodeOf;
    for (const auto& t : p.triangles) {
      Element element;
      for (uint32_t v : t) {
        const auto [at, added] = nodeOf.emplace(v, uint32_t(mesh.nodes.size()));
        if (added) {
          checkLimit(document.path(), mesh.nodes.size() + 1, kMaxSolutionNodes, "vertices in the COLOR_0 mesh");
          Node node;
          node.position = p.positions[v];
          for (int k = 0; k < 3; ++k) node.B[k] = linearValue(colours[v][k], 0.0, encoding);
          mesh.nodes.push_back(node);
        }
        element.corners.push_back(at->second);
      }
      element.material = p.material;
      mesh.elements.push_back(std::move(element));
    }
  };
  reading.scene = importScene(document, imported.warnings, addPrimitive, false);
  reading.isMesh =
      options.readAs == ReadAs::Solution || (options.readAs == ReadAs::Auto && reading.scene.emitters().empty());
  if (!reading.isMesh) {
    // Read again as the scene it is, COLOR_0 multiplying rho.
    mesh = {};
    imported.warnings.clear();
    reading.scene = importScene(document, imported.warnings);
    imported.warnings.push_back(
        "COLOR_0 read as a factor of rho: a file with an emitter is a scene "
        "(--read-as solution reads B from COLOR_0)");
    return reading;
  }
  if (withoutColours > 0)
    imported.warnings.push_back(std::to_string(withoutColours) + " primitive(s) without COLOR_0 left out of the mesh");
  mesh.materials = reading.scene.materials;
  imported.valueSource = std::string("COLOR_0 (") + (integerColours ? "normalized integers" : "float") + "), " +
                         (options.colours == ColourEncoding::Srgb ? "sRGB-decoded to linear (--colours srgb)"
                                                                  : "linear as glTF defines it");
  imported.reflectanceFromFile = true;
  finishImportedMesh(imported, document.path());
  return reading;
}

}  // namespace radview
