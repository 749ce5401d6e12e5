#pragma once
// The radiosity mesh: nodes carrying radiosity B (and optionally its surface gradient),
// elements that are polygons of nodes (linear, or quadratic with mid-edge nodes), and
// discontinuity edges tagged with the continuity the radiosity function has across them.
// C&W ch. 8 builds such meshes; §9.2 renders them.
#include "core/types.h"
#include "scene/scene.h"

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace radview {

// Continuity of B across an edge (Salesin, Lischinski, DeRose 1992): C-1 the value jumps
// (a shadow edge cast by a touching occluder), C0 the value is continuous but its derivative
// jumps (a penumbra boundary), C1 smooth.
enum class Continuity : int8_t { Cm1 = -1, C0 = 0, C1 = 1 };
const char* toString(Continuity c);  // "C-1", "C0", "C1"

struct Node {
  Vec3 position{0.0};
  Rgb B{0.0};
  // Surface gradient of each channel of B (gradient[0] is grad B_r), world space. Meaningful
  // only when RadiosityMesh::hasGradients.
  std::array<Vec3, 3> gradient{};
  // The standard error of each channel of B, as the solver estimated it from its own samples
  // (ProgressiveRefinement: the spread of its visibility estimates). Meaningful only when
  // RadiosityMesh::hasStandardErrors.
  Rgb standardError{0.0};
};

enum class ElementOrder : int { Linear = 1, Quadratic = 2 };

struct Element {
  // Corner nodes, counter-clockwise about the surface normal. Any simple polygon.
  std::vector<uint32_t> corners;
  // Quadratic elements only: midEdge[i] is the node on the edge corners[i] -> corners[i+1].
  std::vector<uint32_t> midEdge;
  int material = 0;
  int surface = -1;  // the scene polygon this element meshes, or -1 if unknown

  ElementOrder order() const { return midEdge.empty() ? ElementOrder::Linear : ElementOrder::Quadratic; }
};

// An element edge across which B is not C1. Nodes a and b are the edge's end nodes on one of
// its sides; across a C-1 edge the other side has its own nodes at the same positions.
struct DiscontinuityEdge {
  uint32_t a = 0, b = 0;
  Continuity order = Continuity::C0;
};

struct RadiosityMesh {
  std::vector<Node> nodes;
  std::vector<Element> elements;
  std::vector<Material> materials;
  std::vector<DiscontinuityEdge> discontinuities;
  bool hasGradients = false;
  bool hasStandardErrors = false;  // solutions whose solver estimated them; other meshes lack them

  Bounds bounds() const;
  std::vector<Vec3> cornerPositions(size_t element) const;
  Vec3 elementNormal(size_t element) const;  // unit normal of the corner polygon
  // The element's flat-shading value: the mean of its nodal values (corners and mid-edges).
  Rgb meanB(size_t element) const;
};

// Throws Error("<source>: ...") naming the first inconsistency: an index out of range, an
// element with fewer than 3 corners or a mid-edge list of the wrong length, a repeated
// corner, a non-finite position, radiosity or gradient, a standard error that is negative or not
// finite, a bad continuity order.
void validateMesh(const RadiosityMesh& mesh, const std::string& source);

std::ostream& operator<<(std::ostream& os, const Node& n);
std::ostream& operator<<(std::ostream& os, const Element& e);

}  // namespace radview
