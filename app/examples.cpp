#include "app/examples.h"

#include "core/error.h"

#include <filesystem>

namespace radview {

const std::vector<Example>& bundledExamples() {
  static const std::vector<Example> examples = {
      {"cornell_box_solved.glb", "Cornell box, solved",
       "radview solve --discontinuity-meshing: shadows, colour bleeding, C-1 edges at the blocks' feet, "
       "T-vertices where subdivision stopped (E, D, T show them)",
       Method::CloughTocher},
      {"cornell_box.gltf", "Cornell box, the scene",
       "the measured geometry and materials, solved here as it opens (direct light first); 0 path traces "
       "the true image", Method::Gouraud},
      {"fig9_8_quad.gltf", "Fig. 9.8: one quad, four values",
       "scanline Gouraud depends on the view: R turns it 45 degrees, the centre goes 0.5 -> 0.8; bilinear (4) "
       "stays 0.5",
       Method::ScanlineGouraud, true},
      {"fig9_14.gltf", "Fig. 9.14: a discontinuity mesh",
       "Gouraud's Mach bands (2) against C1 quadratic (6) and Clough-Tocher (7), continuity relaxed at the "
       "shadow edges",
       Method::Gouraud, true, true},
      {"t_vertices.gltf", "T-vertices",
       "two coarse quads beside eight fine ones: Gouraud's shading seam at the T-vertices; B repairs it",
       Method::Gouraud, true, false, true},
      {"discontinuities.gltf", "C0 and C-1 edges",
       "Clough-Tocher, smooth everywhere but across the edges tagged C0 (a kink) and C-1 (a step); H lifts "
       "the radiosity surface to show them",
       Method::CloughTocher, false, true},
  };
  return examples;
}

const Example* exampleForFile(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  for (const Example& example : bundledExamples())
    if (example.file == name) return &example;
  return nullptr;
}

std::string examplePath(const Example& example) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    for (const fs::path& dir : {exe.parent_path() / "assets", exe.parent_path() / "../share/radview/assets"})
      if (fs::exists(dir / example.file)) return (dir / example.file).lexically_normal().string();
  }
  const fs::path source = fs::path(RADVIEW_SOURCE_ASSETS) / example.file;
  if (fs::exists(source)) return source.string();
  throw Error("the bundled file " + example.file + " is neither next to the radview binary nor in " +
              RADVIEW_SOURCE_ASSETS);
}

}  // namespace radview
