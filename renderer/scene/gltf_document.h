#pragma once
// An opened glTF 2.0 file (.gltf or .glb) and validated reading of its accessors.
//
// tinygltf parses the JSON and the GLB container but checks little else (index ranges, byte
// ranges, minVersion, extensionsRequired; gl/README.md, "Platform notes"). This class
// refuses what radview cannot honour at open time, and reads accessor data only through
// checks that trust nothing in the file: every index, offset, stride and count is checked in
// 64-bit arithmetic that cannot overflow before a byte is touched.
#include "core/types.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace radview {

// glTF component types (accessor.componentType in the glTF 2.0 spec) as bits, so a reader can say
// which ones a use allows.
enum ComponentTypeBit : unsigned {
  kByte = 1u << 0,           // 5120
  kUnsignedByte = 1u << 1,   // 5121
  kShort = 1u << 2,          // 5122
  kUnsignedShort = 1u << 3,  // 5123
  kUnsignedInt = 1u << 4,    // 5125
  kFloat = 1u << 5,          // 5126
};
constexpr unsigned kUnsignedIntegerTypes = kUnsignedByte | kUnsignedShort | kUnsignedInt;

// What a caller expects of an accessor. `what` names the use in error messages
// ("mesh 2 primitive 0 POSITION").
struct AccessorRequest {
  std::string what;
  int components = 3;                // 1 SCALAR, 2 VEC2, 3 VEC3, 4 VEC4
  unsigned componentTypes = kFloat;  // the ComponentTypeBits allowed
  // Whether integer data may be `normalized` (decoded to [0,1] or [-1,1] as the spec says).
  // Integer data that is not normalized is read as its exact integer value.
  bool normalizedAllowed = false;
};

class GltfDocument {
 public:
  // Opens and parses `path` (.gltf or .glb by extension). Throws Error(path, ...) when the file
  // is missing, not a regular file, empty, of an unknown extension, fails to parse, has an
  // asset.version or minVersion other than 2.x / 2.0, or requires an extension radview does
  // not support. Images are never decoded: radview draws no textures.
  explicit GltfDocument(const std::string& path);
  ~GltfDocument();
  GltfDocument(GltfDocument&&) noexcept;
  GltfDocument& operator=(GltfDocument&&) noexcept;

  const std::string& path() const { return path_; }
  const tinygltf::Model& model() const { return *model_; }
  // Things a user may want to know that did not stop the load (tinygltf's warnings, images
  // that were not decoded). One line each.
  const std::vector<std::string>& warnings() const { return warnings_; }
  bool usesExtension(const std::string& name) const;

  // Reads accessor `index` as request.components doubles per element, element-major, after
  // checking it completely (indices, byte ranges, stride, type, component type, normalization,
  // sparse substitution, finiteness of floats). Throws Error(path, "<what>: accessor N: ...").
  std::vector<double> readAccessor(int index, const AccessorRequest& request) const;
  std::vector<Vec3> readVec3(int index, const AccessorRequest& request) const;
  // An unsigned integer SCALAR accessor (not normalized) whose every value is < `limit`.
  // For `indices`, also refuses the primitive-restart values glTF forbids there.
  enum class Restart { Allowed, Forbidden };
  std::vector<uint32_t> readUnsigned(int index, const std::string& what, uint64_t limit,
                                     Restart restart = Restart::Allowed) const;

 private:
  std::string path_;
  std::unique_ptr<tinygltf::Model> model_;
  std::vector<std::string> warnings_;
};

}  // namespace radview
