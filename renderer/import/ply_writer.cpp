#include "import/ply_writer.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <cfloat>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace radview {

namespace {

// Little-endian bytes of `value` (radview builds only for little-endian hosts: x86-64, arm64).
template <class T>
void put(std::string& out, T value) {
  static_assert(std::is_arithmetic_v<T>);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace

std::string plyBytes(const RadiosityMesh& mesh, const std::string& source) {
  validateMesh(mesh, source);
  size_t largest = 0;
  for (const Element& e : mesh.elements) {
    if (e.order() != ElementOrder::Linear)
      throw Error(source, "has quadratic elements, which PLY faces cannot hold (they have no mid-edge nodes)");
    largest = std::max(largest, e.corners.size());
  }
  // Every value is written as float32: one past its range would read back as infinity.
  auto fits = [](const Vec3& v) {
    return std::abs(v.x) <= FLT_MAX && std::abs(v.y) <= FLT_MAX && std::abs(v.z) <= FLT_MAX;
  };
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    bool ok = fits(mesh.nodes[n].position) && fits(mesh.nodes[n].B);
    if (mesh.hasGradients)
      for (const Vec3& g : mesh.nodes[n].gradient) ok = ok && fits(g);
    if (!ok) throw Error(source, "node " + std::to_string(n) + " has a value that does not fit in float32");
  }
  const bool wideCounts = largest > 255;
  size_t tagged = 0;  // C1 edges are no discontinuity: not written
  for (const DiscontinuityEdge& d : mesh.discontinuities) tagged += d.order != Continuity::C1;
  std::string out =
      "ply\nformat binary_little_endian 1.0\n"
      "comment radview radiosity mesh: red green blue are the nodal radiosity B, linear and unclamped\n"
      "comment edge: discontinuity edges, continuity -1 (value jumps) or 0 (derivative jumps)\n";
  out += "element vertex " + std::to_string(mesh.nodes.size()) + "\n";
  out += "property float x\nproperty float y\nproperty float z\n";
  out += "property float red\nproperty float green\nproperty float blue\n";
  if (mesh.hasGradients)
    for (const char* channel : kGradientChannels)
      for (const char* axis : {"x", "y", "z"})
        out += std::string("property float gradient_") + channel + "_" + axis + "\n";
  out += "element face " + std::to_string(mesh.elements.size()) + "\n";
  out += std::string("property list ") + (wideCounts ? "uint" : "uchar") + " uint vertex_indices\n";
  out += "element edge " + std::to_string(tagged) + "\n";
  out += "property int vertex1\nproperty int vertex2\nproperty char continuity\n";
  out += "end_header\n";
  out.reserve(out.size() + mesh.nodes.size() * 24 + mesh.elements.size() * 17 + mesh.discontinuities.size() * 9);
  for (const Node& n : mesh.nodes) {
    for (int k = 0; k < 3; ++k) put(out, float(n.position[k]));
    for (int k = 0; k < 3; ++k) put(out, float(n.B[k]));
    if (mesh.hasGradients)
      for (const Vec3& g : n.gradient)
        for (int k = 0; k < 3; ++k) put(out, float(g[k]));
  }
  for (const Element& e : mesh.elements) {
    if (wideCounts)
      put(out, uint32_t(e.corners.size()));
    else
      put(out, uint8_t(e.corners.size()));
    for (uint32_t c : e.corners) put(out, c);
  }
  for (const DiscontinuityEdge& d : mesh.discontinuities) {
    if (d.order == Continuity::C1) continue;
    put(out, int32_t(d.a));
    put(out, int32_t(d.b));
    put(out, int8_t(d.order));
  }
  return out;
}

void writePly(const RadiosityMesh& mesh, const std::string& path) { writeFileAtomically(path, plyBytes(mesh, path)); }

}  // namespace radview
