#include "mesh/radiosity_mesh.h"

#include "core/error.h"
#include "geom/polygon.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace radview {

const char* toString(Continuity c) {
  switch (c) {
    case Continuity::Cm1:
      return "C-1";
    case Continuity::C0:
      return "C0";
    case Continuity::C1:
      return "C1";
  }
  return "C?";
}

Bounds RadiosityMesh::bounds() const {
  Bounds b;
  for (const Node& n : nodes) b.extend(n.position);
  return b;
}

std::vector<Vec3> RadiosityMesh::cornerPositions(size_t element) const {
  std::vector<Vec3> out;
  out.reserve(elements[element].corners.size());
  for (uint32_t c : elements[element].corners) out.push_back(nodes[c].position);
  return out;
}

Vec3 RadiosityMesh::elementNormal(size_t element) const { return unitNormal(cornerPositions(element)); }

Rgb RadiosityMesh::meanB(size_t element) const {
  const Element& e = elements[element];
  Rgb sum(0.0);
  for (uint32_t c : e.corners) sum += nodes[c].B;
  for (uint32_t m : e.midEdge) sum += nodes[m].B;
  return sum / double(e.corners.size() + e.midEdge.size());
}

namespace {

template <typename... Args>
[[noreturn]] void fail(const std::string& source, Args&&... parts) {
  std::ostringstream os;
  (os << ... << parts);
  throw Error(source, os.str());
}

}  // namespace

void validateMesh(const RadiosityMesh& mesh, const std::string& source) {
  const size_t nodeCount = mesh.nodes.size();
  for (size_t i = 0; i < nodeCount; ++i) {
    const Node& n = mesh.nodes[i];
    if (!isFinite(n.position)) fail(source, "node ", i, " has a non-finite position");
    if (!isFinite(n.B)) fail(source, "node ", i, " has a non-finite radiosity");
    if (mesh.hasGradients)
      for (const Vec3& g : n.gradient)
        if (!isFinite(g)) fail(source, "node ", i, " has a non-finite radiosity gradient");
    if (mesh.hasStandardErrors && !(isFinite(n.standardError) && glm::all(glm::greaterThanEqual(n.standardError, Rgb(0.0)))))
      fail(source, "node ", i, " has a standard error that is negative or not finite");
  }
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& el = mesh.elements[e];
    if (el.corners.size() < 3) fail(source, "element ", e, " has ", el.corners.size(), " corners (at least 3 needed)");
    if (!el.midEdge.empty() && el.midEdge.size() != el.corners.size())
      fail(source, "element ", e, " has ", el.midEdge.size(), " mid-edge nodes for ", el.corners.size(), " edges");
    std::vector<uint32_t> all = el.corners;
    all.insert(all.end(), el.midEdge.begin(), el.midEdge.end());
    for (uint32_t n : all)
      if (n >= nodeCount) fail(source, "element ", e, " refers to node ", n, " of ", nodeCount);
    std::sort(all.begin(), all.end());
    if (std::adjacent_find(all.begin(), all.end()) != all.end()) fail(source, "element ", e, " uses a node twice");
    if (el.material < 0 || el.material >= static_cast<int>(mesh.materials.size()))
      fail(source, "element ", e, " refers to material ", el.material, " of ", mesh.materials.size());
    // Rendering and interpolation cut every element into triangles: one that cannot be cut
    // (zero area, self-intersecting) is refused here, with the file named.
    try {
      triangulatePolygon(mesh.cornerPositions(e));
    } catch (const Error& error) {
      fail(source, "element ", e, ": ", error.what());
    }
  }
  for (size_t d = 0; d < mesh.discontinuities.size(); ++d) {
    const DiscontinuityEdge& edge = mesh.discontinuities[d];
    if (edge.a >= nodeCount || edge.b >= nodeCount)
      fail(source, "discontinuity edge ", d, " refers to a node out of range");
    if (edge.order != Continuity::Cm1 && edge.order != Continuity::C0 && edge.order != Continuity::C1)
      fail(source, "discontinuity edge ", d, " has continuity order ", int(edge.order), " (expected -1, 0 or 1)");
  }
}

std::ostream& operator<<(std::ostream& os, const Node& n) {
  return os << "Node{p=" << n.position << " B=" << n.B << '}';
}

std::ostream& operator<<(std::ostream& os, const Element& e) {
  os << "Element{corners=[";
  for (size_t i = 0; i < e.corners.size(); ++i) os << (i ? "," : "") << e.corners[i];
  os << "]";
  if (!e.midEdge.empty()) {
    os << " mid=[";
    for (size_t i = 0; i < e.midEdge.size(); ++i) os << (i ? "," : "") << e.midEdge[i];
    os << "]";
  }
  return os << " material=" << e.material << '}';
}

}  // namespace radview
