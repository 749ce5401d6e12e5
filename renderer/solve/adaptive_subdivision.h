#pragma once
// Adaptive subdivision of a radiosity mesh (C&W §8.4; Cohen et al. 1986): elements whose nodal
// values differ too much on display are split in four. A neighbour that is not split keeps the
// new mid-edge node as a T-vertex (C&W §9.2), which radview keeps and shows; the mid-edge
// node is shared as soon as the neighbour splits too.
#include "mesh/radiosity_mesh.h"
#include "solve/view_importance.h"

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace radview {

struct SubdivisionCriteria {
  // Largest allowed spread of an element's nodal display values, in 8-bit display steps: the
  // value is 255 * sRGB(clamp(Y(B) * toneMapScale, 0, 1)), Y the Rec. 709 luminance and
  // toneMapScale the solution file's (solution_file.h), so a step is one level of what a
  // viewer shows for the file.
  double tolerance = 8.0;
  // > 0: elements are also split where linear interpolation is off by more than this fraction
  // of B at their centre (solve/interpolation_error.h; of 1 % of display white where B is
  // darker): the spread of bright, smooth light is a few display steps where its curvature
  // makes the interpolant, and the light the element shoots, a percent low. 0: spread only.
  double relativeError = 0.0;
  // No element is split whose longest edge is below twice this (its children would be smaller).
  double minElementSize = 0.0;
  // Splits stop where they would take the mesh above this many elements; the largest spreads
  // are split first.
  size_t maxElements = 20000;
  // 2:1 balance: after each round, elements are also split until no element edge holds more
  // than one T-vertex, that is until neighbours differ by at most one level of subdivision
  // (the restricted quadtrees of finite-element meshing), whatever their spread.
  bool balance = false;
  // Views to mesh for (C&W §9.3, solve/view_importance.h); none: the view-independent criterion.
  // With views, an element is split only where their pixels see its front side, and under the
  // element budget the splits that remove the most squared display error from the views come
  // first: spread^2 times the pixels that see the element (the sum over those pixels of an
  // interpolation error that scales with the spread), rather than the largest spread anywhere.
  // 2:1 balance too splits only elements the views see.
  std::vector<SolveView> views;
};

// The display value a tolerance is measured in (see SubdivisionCriteria::tolerance).
double displayValue(const Rgb& B, double toneMapScale);

// The elements to split, in order of decreasing excess s = max(spread / tolerance, relative
// error / relativeError) (with views: of s^2 times the pixels that see them, seen elements
// only): s above 1, not emitting (emitters display saturated), large enough, and within
// maxElements.
std::vector<uint32_t> elementsToSplit(const RadiosityMesh& valued, const SubdivisionCriteria& criteria);

// The elements that 2:1 balance splits (SubdivisionCriteria::balance): those with an edge that
// holds T-vertices at two or more positions (nodes duplicated along a C-1 edge count once) and
// that elementsToSplit would split but for their spread (not emitting, not below
// minElementSize, splittable, seen by the views if there are any), in element order, as many
// as keep the mesh within maxElements.
std::vector<uint32_t> unbalancedElements(const RadiosityMesh& mesh, const SubdivisionCriteria& criteria);

// Splits elements of one mesh, remembering every edge's mid node so that neighbours split later
// share it. Triangles split into 4 triangles, convex quads into 4 quads through a centre node,
// other convex polygons into one quad per corner; a concave element is never split. Children
// keep their parent's material, surface, orientation and order (a quadratic element's children
// are quadratic). A tagged discontinuity edge that is split leaves both halves tagged with
// its order, on both sides of the edge.
class MeshRefiner {
 public:
  // Reads the mesh's existing mid-edge nodes and discontinuity tags (through MeshTopology, so
  // a tag naming one side of a C-1 edge covers the other side too). The mesh must pass
  // validateMesh.
  explicit MeshRefiner(const RadiosityMesh& mesh);

  // Makes every linear element quadratic: one new node at the middle of every edge, shared
  // by the elements on both sides of it (C&W §9.2.2's quadratic elements).
  void makeQuadratic(RadiosityMesh& mesh);

  // Splits the given elements (each at most once, concave ones skipped). The first child takes
  // the parent's index; the others are appended, and parentOf (appended to) gives each
  // appended element's parent. New nodes are appended with B = 0. Returns the elements split.
  size_t split(RadiosityMesh& mesh, const std::vector<uint32_t>& elements, std::vector<uint32_t>& parentOf);

  static bool canSplit(const RadiosityMesh& mesh, uint32_t element);

 private:
  uint32_t midNode(RadiosityMesh& mesh, uint32_t a, uint32_t b);
  uint32_t newNode(RadiosityMesh& mesh, const Vec3& position);
  void retag(RadiosityMesh& mesh) const;

  std::unordered_map<uint64_t, uint32_t> mid_;         // edge (node pair) -> its mid node
  std::unordered_map<uint64_t, Continuity> tagOrder_;  // tagged edges, by node pair
};

}  // namespace radview
