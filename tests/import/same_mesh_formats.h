#pragma once
// One small radiosity mesh written the ways other tools write it: PLY with float colours
// (ASCII), PLY with 8-bit colours (binary big endian), OBJ with `v x y z r g b`, glTF with
// COLOR_0. Two unit quads side by side; along their shared edge the value jumps (two vertices
// at each position there, a C-1 edge as a solver writes it), and one value is above 1.
#include "core/display_transform.h"
#include "core/types.h"
#include "tests/import/import_files.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace radview::test {

struct SameMesh {
  std::vector<Vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                 {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}};
  // Float-exact values; 7.25 is HDR.
  std::vector<Rgb> B = {{0.25, 0.5, 0.75}, {0.5, 0.5, 0.5}, {1, 0.125, 0}, {0, 0, 0.0625},
                        {7.25, 3.5, 1},    {0.375, 1, 0.5}, {0.5, 0, 1},   {2, 2, 2}};
  std::vector<std::array<uint32_t, 4>> quads = {{0, 1, 2, 3}, {4, 5, 6, 7}};

  // The 8-bit display value of a linear value, as a tool writing uchar colours stores it.
  static int byteOf(double linear) { return int(std::lround(srgbEncode(linear) * 255.0)); }
  // What an 8-bit file's value reads back as.
  static double fromByte(int byte) { return srgbDecode(byte / 255.0); }

  std::string plyFloatAscii() const {
    std::string text =
        "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
        "property float red\nproperty float green\nproperty float blue\nelement face 2\n"
        "property list uchar int vertex_indices\nend_header\n";
    for (size_t v = 0; v < positions.size(); ++v) text += number(positions[v]) + " " + number(B[v]) + "\n";
    for (const auto& q : quads)
      text += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " +
              std::to_string(q[3]) + "\n";
    return text;
  }

  std::string plyByteBigEndian() const {
    std::string text =
        "ply\nformat binary_big_endian 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
        "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
        "element face 2\nproperty list uchar uint vertex_indices\nend_header\n";
    PlyBody body(true);
    for (size_t v = 0; v < positions.size(); ++v) {
      for (int k = 0; k < 3; ++k) body.put(float(positions[v][k]));
      for (int k = 0; k < 3; ++k) body.put(uint8_t(byteOf(std::min(B[v][k], 1.0))));
    }
    for (const auto& q : quads) {
      body.put(uint8_t(4));
      for (uint32_t i : q) body.put(i);
    }
    return text + body.bytes();
  }

  std::string obj() const {
    std::string text = "# two quads\n";
    for (size_t v = 0; v < positions.size(); ++v) text += "v " + number(positions[v]) + " " + number(B[v]) + "\n";
    for (const auto& q : quads)
      text += "f " + std::to_string(q[0] + 1) + " " + std::to_string(q[1] + 1) + " " + std::to_string(q[2] + 1) + " " +
              std::to_string(q[3] + 1) + "\n";
    return text;
  }

  // glTF has triangles only: each quad as two, one primitive, COLOR_0 float VEC3.
  std::string gltfColour0(bool withEmitter = false) const {
    std::string bytes;
    auto putFloat = [&](float f) { bytes.append(reinterpret_cast<const char*>(&f), 4); };
    for (const Vec3& p : positions)
      for (int k = 0; k < 3; ++k) putFloat(float(p[k]));
    for (const Rgb& b : B)
      for (int k = 0; k < 3; ++k) putFloat(float(b[k]));
    for (const auto& q : quads)
      for (uint32_t i : {q[0], q[1], q[2], q[0], q[2], q[3]}) bytes.append(reinterpret_cast<const char*>(&i), 4);
    const std::string material = withEmitter ? R"(,"materials":[{"emissiveFactor":[1,1,1]}])" : "";
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"COLOR_0":1},"indices":2)" +
           std::string(withEmitter ? R"(,"material":0)" : "") + R"(}]}],)" +
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":8,"type":"VEC3","min":[0,0,0],"max":[2,1,0]},)"
           R"({"bufferView":0,"byteOffset":96,"componentType":5126,"count":8,"type":"VEC3"},)"
           R"({"bufferView":1,"componentType":5125,"count":12,"type":"SCALAR"}],)"
           R"("bufferViews":[{"buffer":0,"byteLength":192},{"buffer":0,"byteOffset":192,"byteLength":48}],)"
           R"("buffers":[{"byteLength":240,"uri":"data:application/octet-stream;base64,)" +
           base64(bytes) + R"("}])" + material + "}";
  }

 private:
  static std::string number(const Vec3& v) {
    return std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z);
  }
  static std::string base64(const std::string& in) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
      const uint32_t n = uint32_t(uint8_t(in[i])) << 16 | (i + 1 < in.size() ? uint32_t(uint8_t(in[i + 1])) << 8 : 0) |
                         (i + 2 < in.size() ? uint32_t(uint8_t(in[i + 2])) : 0);
      out += table[n >> 18 & 63];
      out += table[n >> 12 & 63];
      out += i + 1 < in.size() ? table[n >> 6 & 63] : '=';
      out += i + 2 < in.size() ? table[n & 63] : '=';
    }
    return out;
  }
};

}  // namespace radview::test
