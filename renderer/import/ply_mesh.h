#pragma once
// A PLY file as a radiosity mesh: its vertices are the nodes (as the file numbers them: two
// vertices at one position stay two nodes), its faces the elements as they are (quads stay
// quads, polygons polygons), B from the vertex colours or a scalar property, discontinuity
// tags from an `edge` element with a `continuity` property (the one radview's PLY export writes).
#include "import/imported_mesh.h"
#include "import/ply_file.h"

#include <string>

namespace radview {

// B comes from, in this order: the scalar `options.valueProperty` (grey), the vertex
// properties red green blue, r g b or diffuse_red diffuse_green diffuse_blue, or a scalar
// named `radiosity` or `B` (grey); converted by options.colours (import/import_options.h).
// Throws Error(path, ...) for a file with no faces (a point cloud), no per-vertex values, a
// face with fewer than 3 vertices or an index out of range or repeated, a non-finite value.
ImportedMesh plyMesh(const PlyFile& ply, const std::string& path, const ImportOptions& options);

// readPly, then plyMesh.
ImportedMesh readPlyMesh(const std::string& path, const ImportOptions& options);

}  // namespace radview
