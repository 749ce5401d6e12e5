#pragma once
// A radiosity mesh read from another tool's file, and the steps every importer shares: the
// colour conventions (import/import_options.h) and the clean-up that makes a face list a mesh.
#include "import/import_options.h"
#include "mesh/radiosity_mesh.h"

#include <string>
#include <vector>

namespace radview {

struct ImportedMesh {
  RadiosityMesh mesh;
  std::string valueSource;            // which data became B and how, for `radview info`
  std::string gatherRefusal;          // why the final gather cannot run on it; empty when it can
  bool reflectanceFromFile = false;   // the elements' rho come from the file (glTF materials)
  std::vector<std::string> warnings;  // one line each
};

// A colour component as linear radiosity. `integerMax` is the largest value of the stored
// integer type (255 for 8 bits), 0 for floats. Auto decodes integers from sRGB and keeps floats.
double linearValue(double stored, double integerMax, ColourEncoding encoding);
// "linear", "sRGB-decoded to linear" or "scaled to [0, 1]": what linearValue did, for messages.
std::string conversionName(bool integerStored, ColourEncoding encoding);

// The material imported meshes get when the file says nothing of reflectance and emission.
Material unknownMaterial();

// Drops elements of (numerically) zero area and nodes no element uses, then checks the result
// with validateMesh. Throws Error(path, ...) when nothing is left or the mesh is inconsistent;
// the warnings say what was dropped.
void finishImportedMesh(ImportedMesh& imported, const std::string& path);

// Applies options.rho and options.emittersAbove (import/import_options.h) to a finished mesh,
// and says in gatherRefusal what the final gather still lacks, naming the options that would
// give it. Throws Error(path, ...) when no element reaches the emitter threshold.
void assumeMaterials(ImportedMesh& imported, const ImportOptions& options, const std::string& path);

}  // namespace radview
