#include "tests/fuzz/mesh_bytes.h"

#include <algorithm>
#include <cmath>

namespace radview::fuzz {

namespace {

class ByteReader {
 public:
  ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  uint8_t u8() { return at_ < size_ ? data_[at_++] : 0; }
  uint16_t u16() {
    const uint16_t lo = u8();
    return uint16_t(lo | (uint16_t(u8()) << 8));
  }
  int16_t i16() { return int16_t(u16()); }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t at_ = 0;
};

class ByteWriter {
 public:
  void u8(uint8_t v) { bytes.push_back(v); }
  void u16(uint16_t v) {
    u8(uint8_t(v & 0xff));
    u8(uint8_t(v >> 8));
  }
  void i16(int16_t v) { u16(uint16_t(v)); }
  std::vector<uint8_t> bytes;
};

constexpr double kPositionUnit = 1.0 / 256.0;
constexpr double kMantissaUnit = 1.0 / 256.0;
constexpr int kDecades = 17;  // 10^-8 .. 10^8
constexpr int kLowestDecade = -8;

}  // namespace

RadiosityMesh decodeMesh(const uint8_t* data, size_t size) {
  ByteReader in(data, size);
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"fuzz", Rgb(0.5), Rgb(0.0)});
  const size_t nodeCount = std::min<size_t>(in.u16(), kMaxFuzzNodes);
  const size_t elementCount = std::min<size_t>(in.u16(), kMaxFuzzElements);
  if (nodeCount == 0) return mesh;
  mesh.nodes.resize(nodeCount);
  for (Node& node : mesh.nodes) {
    for (int k = 0; k < 3; ++k) node.position[k] = in.i16() * kPositionUnit;
    for (int c = 0; c < 3; ++c) node.B[c] = in.u16() * kMantissaUnit;
    node.B *= std::pow(10.0, in.u8() % kDecades + kLowestDecade);
  }
  const auto nodeIndex = [&] { return uint32_t(in.u16() % nodeCount); };
  mesh.elements.resize(elementCount);
  for (Element& element : mesh.elements) {
    const uint8_t shape = in.u8();
    element.corners.resize(3 + (shape & 3));
    for (uint32_t& corner : element.corners) corner = nodeIndex();
    if (shape & 4) {
      element.midEdge.resize(element.corners.size());
      for (uint32_t& mid : element.midEdge) mid = nodeIndex();
    }
  }
  const size_t discontinuityCount = std::min<size_t>(in.u16(), kMaxFuzzDiscontinuities);
  mesh.discontinuities.resize(discontinuityCount);
  for (DiscontinuityEdge& edge : mesh.discontinuities) {
    edge.a = nodeIndex();
    edge.b = nodeIndex();
    edge.order = Continuity(in.u8() % 3 - 1);
  }
  return mesh;
}

std::vector<uint8_t> encodeMesh(const RadiosityMesh& mesh) {
  ByteWriter out;
  const size_t nodeCount = std::min(mesh.nodes.size(), kMaxFuzzNodes);
  const size_t elementCount = std::min(mesh.elements.size(), kMaxFuzzElements);
  out.u16(uint16_t(nodeCount));
  out.u16(uint16_t(elementCount));

  const Bounds bounds = mesh.bounds();
  const Vec3 center = 0.5 * (bounds.lo + bounds.hi);
  double extent = 0.0;
  for (int k = 0; k < 3; ++k) extent = std::max(extent, bounds.hi[k] - bounds.lo[k]);
  const double scale = extent > 0.0 ? 2.0 * 30000.0 / extent : 1.0;
  for (size_t i = 0; i < nodeCount; ++i) {
    const Node& node = mesh.nodes[i];
    for (int k = 0; k < 3; ++k) out.i16(int16_t(std::lround((node.position[k] - center[k]) * scale)));
    // One decade for the node: its largest channel's mantissa near the top of the u16 range.
    const double largest = std::max({node.B.r, node.B.g, node.B.b});
    int decade = kLowestDecade;
    while (decade < kLowestDecade + kDecades - 1 && largest > 200.0 * std::pow(10.0, decade)) ++decade;
    const double unit = std::pow(10.0, decade);
    for (int c = 0; c < 3; ++c)
      out.u16(uint16_t(std::clamp(std::lround(node.B[c] / unit / kMantissaUnit), 0L, 65535L)));
    out.u8(uint8_t(decade - kLowestDecade));
  }
  for (size_t e = 0; e < elementCount; ++e) {
    const Element& element = mesh.elements[e];
    const size_t corners = std::clamp<size_t>(element.corners.size(), 3, 6);
    out.u8(uint8_t((corners - 3) | (element.midEdge.empty() ? 0 : 4)));
    for (size_t k = 0; k < corners; ++k) out.u16(uint16_t(element.corners[k % element.corners.size()]));
    if (!element.midEdge.empty())
      for (size_t k = 0; k < corners; ++k) out.u16(uint16_t(element.midEdge[k % element.midEdge.size()]));
  }
  const size_t discontinuityCount = std::min(mesh.discontinuities.size(), kMaxFuzzDiscontinuities);
  out.u16(uint16_t(discontinuityCount));
  for (size_t i = 0; i < discontinuityCount; ++i) {
    const DiscontinuityEdge& edge = mesh.discontinuities[i];
    out.u16(uint16_t(edge.a));
    out.u16(uint16_t(edge.b));
    out.u8(uint8_t(int(edge.order) + 1));
  }
  return out.bytes;
}

}  // namespace radview::fuzz
