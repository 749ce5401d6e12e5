#pragma once
// Every way radview draws a picture, in one table: the interpolation methods (C&W §9.2), which
// reconstruct B from the nodal values, and the ray tracers, which estimate it per pixel on the
// CPU (the final gather of §9.3.1 and the path-traced truth). For each, its one name on the
// command line (`--method`), in files and in messages, its label and key in the viewer, where
// the book treats it, and what it is. The command line, the panel, the key handler, the help
// text, `bench`, the CPU interpolants (interpolant.h) and the GPU renderer (gl/mesh_renderer.h)
// all read it, so a new method is one entry here plus its CPU and GLSL code.
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
  ThinPlate,        // Clough-Tocher over a thin-plate smoothing spline's values: approximates, not interpolates
};

// What the GPU renderer (gl/mesh_renderer.h) draws a method with: its pass, and for the piece
// passes which pieces gl/method_pieces.h builds. Every function that acts on it switches over
// all of its values, so a value added here is a compile error (-Werror=switch) wherever it is
// not yet drawn.
enum class GpuPass : int {
  Triangles,           // the element triangles, the rasteriser interpolating (flat, Gouraud)
  ScanlinePolygons,    // per pixel from each polygon: down its edges, then across the scanline
  BilinearPolygons,    // per pixel from each quad: its bilinear parameters inverted
  LagrangePieces,      // quadratic Lagrange triangles, serendipity quads per pixel (C0)
  PowellSabinPieces,   // quadratic Bezier pieces of the Powell-Sabin split (C1)
  CloughTocherPieces,  // cubic Bezier pieces of the Clough-Tocher split (C1)
};

// Drawn from Bezier or Lagrange pieces: exact per pixel, or tessellated to a flatness criterion.
bool drawsPieces(GpuPass pass);
// The pieces' polynomial degree (2 or 3); 0 for a pass without pieces.
int pieceDegree(GpuPass pass);
// Per pixel, the pieces' control nets go through the deferred resolve (a G-buffer of piece and
// barycentric coordinates, gl/deferred_pass.h) rather than being drawn one by one.
bool resolvesDeferred(GpuPass pass);

struct MethodInfo {
  Method method;
  std::string name;     // "gouraud": the command line's, files' and messages' name
  std::string alias;    // an older name still accepted ("linear"), or empty
  std::string label;    // "Gouraud": the viewer's
  char key;             // the viewer's number key
  std::string section;  // where the book treats it: "C&W §9.2, fig. 9.7"
  std::string summary;  // one line: --help, the panel's tooltip
  bool viewDependent;   // the value depends on how the element lies on the screen
  GpuPass gpu;
  bool c1;  // C1 across element edges (relaxed where the mesh tags them)
  bool bezierPieces() const { return drawsPieces(gpu); }
};

// The pictures drawn by casting rays per pixel rather than from the nodal values.
enum class RayTracer : int {
  FinalGather,  // eq. 9.9 per pixel over the solution (C&W §9.3.1): the interpolants' yardstick
  PathTrace,    // the radiosity equation itself by path tracing, no solution: the truth
};

struct RayTracerInfo {
  RayTracer tracer;
  std::string name;     // "final-gather": a --method name like the interpolants'
  std::string label;    // "Final gather": the viewer's
  std::string noun;     // "final gather": in messages ("the final gather needs ...")
  char key;             // the viewer's number key
  std::string section;  // where the book treats it
  std::string summary;  // one line: --help, the panel's tooltip
  bool needsSolution;   // integrates the solution's B (the final gather), or needs none
};

// In enum order.
const std::vector<MethodInfo>& methodRegistry();
const std::vector<RayTracerInfo>& rayTracerRegistry();
const RayTracerInfo& rayTracerInfo(RayTracer tracer);
// The ray tracer a --method name names; none for an interpolation method's name.
std::optional<RayTracer> rayTracerFromName(const std::string& name);
// The ray tracer the viewer's key selects, if any.
std::optional<RayTracer> rayTracerForKey(char key);
// Every --method name a picture can be drawn with: the methods', then the ray tracers'.
std::vector<std::string> pictureMethodNames();
const MethodInfo& methodInfo(Method method);
const std::string& methodName(Method method);
// Every method's name, in enum order; with `viewIndependentOnly`, those a point of the surface
// determines alone (what the final gather can integrate).
std::vector<std::string> methodNames(bool viewIndependentOnly = false);
// A name or an alias. Throws Error naming the known names.
Method methodFromName(const std::string& name);
// The interpolation method the viewer's key selects, if any.
std::optional<Method> methodForKey(char key);

}  // namespace radview
