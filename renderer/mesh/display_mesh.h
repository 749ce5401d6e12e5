#pragma once
// What the GPU draws of a radiosity mesh: elements cut into triangles whose vertices carry
// the nodal radiosities, and the element edges as line segments. Built on the CPU once per
// mesh; no OpenGL here.
#include "mesh/radiosity_mesh.h"
#include "mesh/topology.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace radview {

struct DisplayVertex {
  glm::vec3 position;
  glm::vec3 B;      // the node's radiosity
  glm::vec3 Bflat;  // the mean of the element's nodal values (flat shading: RadiosityMesh::meanB)
  uint32_t element;
};

struct OverlayVertex {
  glm::vec3 position;
  glm::vec4 colour;
};

// Overlay colours, also the panel's legend.
inline constexpr glm::vec4 kDiscontinuityCm1Colour{1.0f, 0.25f, 0.2f, 1.0f};  // C-1: value jumps
inline constexpr glm::vec4 kDiscontinuityC0Colour{1.0f, 0.85f, 0.1f, 1.0f};   // C0: derivative jumps
inline constexpr glm::vec4 kTVertexColour{1.0f, 0.1f, 1.0f, 1.0f};
inline constexpr glm::vec4 kSplitLineColour{0.1f, 0.9f, 0.9f, 1.0f};      // Bezier piece boundaries
inline constexpr glm::vec4 kTessellationColour{0.2f, 0.35f, 1.0f, 1.0f};  // generated triangles
inline constexpr glm::vec4 kControlNetColour{1.0f, 0.55f, 0.1f, 1.0f};    // the surface's Bezier control net

// The overlays of a mesh: what is drawn over its surfaces. Its triangles (displayTriangles) are
// built apart, only for the methods that draw them.
struct DisplayMesh {
  std::vector<glm::vec3> elementEdges;            // two points per segment, each element edge once
  std::vector<OverlayVertex> discontinuityEdges;  // two per segment, coloured by order; C1 tags not drawn
  std::vector<OverlayVertex> tVertices;           // one marker each (MeshTopology::tVertices)
};

// The overlays; `topology` is the mesh's own (MeshTopology(mesh)). An element edge is one line
// however many elements and nodes share its positions (a C-1 edge's two sides too), so that a
// continuity edit, which only splits and joins nodes, leaves the lines as they are: with
// `elementEdges` false they are not built.
DisplayMesh buildDisplayMesh(const RadiosityMesh& mesh, const MeshTopology& topology, bool elementEdges = true);

// The triangles the GPU draws of the elements, three vertices each, carrying the nodal values
// `value` (B, or the standard-error view's &Node::standardError).
// Elements are drawn as watertightTriangles. Linear elements are triangulated over their corners (triangulatePolygon: a
// fan when strictly convex, else a constrained Delaunay triangulation, so a T-vertex listed as a corner gets no
// zero-area triangle). Quadratic triangles are cut at their mid-edge nodes into four triangles, so Gouraud shading
// passes through all six nodal values; other quadratic polygons are cut over their corners only (their mid-edge values
// are shown by the higher-order methods). Built on every core.
std::vector<DisplayVertex> displayTriangles(const RadiosityMesh& mesh, const MeshTopology& topology,
                                            Rgb Node::*value = &Node::B);

// A corner of a triangle the GPU draws of an element: at a node's position, with the value the
// element itself has there (the node's own B, or at a neighbour's T-vertex the element's linear
// interpolation along its edge).
struct DrawnCorner {
  uint32_t node = 0;
  Rgb B{0.0};
};

// MeshTopology's T-vertices, listed by the element whose edge each lies on.
std::vector<std::vector<TVertex>> tVerticesByElement(const RadiosityMesh& mesh, const MeshTopology& topology);

// elementTriangles with the element's T-vertices (its list from tVerticesByElement) made
// corners of its outline, so that both sides of a T-junction are drawn through the same
// vertices, while the element keeps its own interpolation: each triangle along an edge with
// T-vertices is fanned through them from its opposite corner, and a T-vertex gets the value
// interpolated linearly along that edge, where the triangle had it already (Gouraud, flat and
// the per-pixel methods show the same picture). Without this the rasteriser, which snaps
// vertices to its sub-pixel grid, can pass a pixel centre between the neighbour's edges through
// the T-vertex and the element's straight edge: a single background pixel in a wall of the
// solved Cornell box (C&W §9.2 on T-vertices; tests/gl/extremes_render_test.cpp).
std::vector<std::array<DrawnCorner, 3>> watertightTriangles(const RadiosityMesh& mesh, size_t element,
                                                            const std::vector<TVertex>& tVertices,
                                                            Rgb Node::*value = &Node::B);

// The triangles (node indices) buildDisplayMesh draws for one element. `firstCorner` starts
// the corner-polygon triangulation at another corner: for a quad, 0 cuts along the diagonal
// 0-2 and 1 along 1-3 (fig. 9.7's two pictures of the same data).
std::vector<std::array<uint32_t, 3>> elementTriangles(const RadiosityMesh& mesh, size_t element,
                                                      size_t firstCorner = 0);

}  // namespace radview
