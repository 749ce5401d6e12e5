#pragma once
// Every interpolation method radview shows, in one table (C&W §9.2): its one name on the
// command line, in files and in messages, its label and key in the viewer, where the book
// treats it, and what it is. The command line, the panel, the key handler, the help text,
// `bench`, the CPU interpolants (interpolant.h) and the GPU renderer (gl/mesh_renderer.h) all
// read it, so a new method is one entry here plus its CPU and GLSL code.
#include <optional>
#include <string>
#include <vector>

namespace radview {

enum class Method : int {
  Flat,             // the element's mean nodal value
  Gouraud,          // linear on a triangulation of each element (for quads: one diagonal)
  ScanlineGouraud,  // down the polygon's edges, then across the scanline: depends on the view
  Bilinear,         // quads in their bilinear parameter space (orientation invariant)
  Quadratic,        // Lagrange on quadratic elements (vertex and mid-edge nodes), C0
  C1Quadratic,      // Powell-Sabin split, quadratic Bezier pieces (Reichert), C1
  CloughTocher,     // three cubic Bezier pieces per triangle, C1 with relaxations (Salesin et al.)
};

// How the GPU renderer (gl/mesh_renderer.h) draws a method.
enum class GpuPath : int {
  Triangles,     // the element triangles, the rasteriser interpolating (flat, Gouraud)
  Polygons,      // per pixel from each element's polygon (scanline Gouraud, bilinear)
  BezierPieces,  // Bezier or Lagrange pieces: exact per pixel, or tessellated
};

struct MethodInfo {
  Method method;
  std::string name;     // "gouraud": the command line's, files' and messages' name
  std::string alias;    // an older name still accepted ("linear"), or empty
  std::string label;    // "Gouraud": the viewer's
  char key;             // the viewer's number key
  std::string section;  // where the book treats it: "C&W §9.2, fig. 9.7"
  std::string summary;  // one line: --help, the panel's tooltip
  bool viewDependent;   // the value depends on how the element lies on the screen
  GpuPath gpu;
  bool c1;  // C1 across element edges (relaxed where the mesh tags them)
  bool bezierPieces() const { return gpu == GpuPath::BezierPieces; }
};

// In enum order.
const std::vector<MethodInfo>& methodRegistry();
const MethodInfo& methodInfo(Method method);
const std::string& methodName(Method method);
// Every method's name, in enum order; with `viewIndependentOnly`, those a point of the surface
// determines alone (what the final gather can integrate).
std::vector<std::string> methodNames(bool viewIndependentOnly = false);
// A name or an alias. Throws Error naming the known names.
Method methodFromName(const std::string& name);
// The method the viewer's key selects ('1' .. '7'), if any.
std::optional<Method> methodForKey(char key);

}  // namespace radview
