#pragma once
// A glTF file whose primitives carry COLOR_0 (Blender's vertex-colour export, three.js, bakers)
// as a radiosity mesh: the nodes are each primitive's vertices, shared where its indices share
// them; the elements its triangles; B is COLOR_0, linear as the glTF specification defines it.
#include "import/imported_mesh.h"
#include "scene/gltf_document.h"
#include "scene/scene.h"

namespace radview {

// True when some primitive of some mesh has a COLOR_0 attribute.
bool hasVertexColours(const GltfDocument& document);

struct ColourMeshReading {
  Scene scene;            // the file read as a scene, as importScene does (materials, cameras)
  bool isMesh = false;    // whether it is read as a radiosity mesh
  ImportedMesh imported;  // if so, B from COLOR_0, the elements keeping the scene's materials
};

// Reads the scene and, beside it, the mesh, which is kept when options.readAs is Solution, or
// Auto and no material emits. Primitives without COLOR_0 are left out of the mesh (a warning
// says how many). Throws Error(document.path(), ...) as importScene does, and for a
// COLOR_0 accessor that is not VEC3 or VEC4 of float or normalized unsigned byte or short, of
// the wrong count, or with a value that is not finite.
ColourMeshReading readColourMesh(const GltfDocument& document, const ImportOptions& options);

}  // namespace radview
