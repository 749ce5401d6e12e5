#pragma once
// Meshes with vertex colours in the formats Assimp reads (OBJ `v x y z r g b` above all) as
// radiosity meshes. Assimp gives every face corner its own vertex; corners with the same
// position and the same colour are joined into one node again, so a value that jumps across an
// edge (two colours at one position) stays two nodes. Faces keep their corners (no
// triangulation): quads stay quads. An OBJ whose `mtllib` files are beside it gives each face its
// material's reflectance (Kd) and emission (Ke).
#include "import/imported_mesh.h"

#include <string>

namespace radview {

// True for the file extensions this importer takes (Assimp's, less glTF and PLY, which radview
// reads itself).
bool assimpReads(const std::string& path);

// Throws Error(path, ...) for what Assimp refuses (its message), a file without vertex
// colours, a non-finite position or colour, a face that repeats a vertex.
ImportedMesh readAssimpMesh(const std::string& path, const ImportOptions& options);

}  // namespace radview
