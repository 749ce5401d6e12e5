#include "scene/gltf_document.h"

#include "core/error.h"
#include "core/input_file.h"
#include "core/limits.h"
#include "core/strings.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace radview {

// glTF stores little-endian data; the decoding below copies bytes straight into host integers.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "radview reads glTF buffers on little-endian hosts only");

namespace {

namespace fs = std::filesystem;

// Extensions a file may list in extensionsRequired. Anything that changes geometry or the
// diffuse colour and that radview does not decode must stop the load instead.
const char* const kSupportedRequiredExtensions[] = {
    "KHR_mesh_quantization",            // integer positions: decoded by readAccessor
    "KHR_materials_emissive_strength",  // read by the scene import
    "KHR_texture_transform",            // textures are never drawn, so their transforms do not matter
    "KHR_texture_basisu",
    "EXT_texture_webp",
    "RADVIEW_radiosity_mesh",  // radview's own solution files
};

// tinygltf 2.7.0 reports these optional properties as missing yet loads the file. They belong
// to skins and animations, which radview ignores, so they are warnings rather than errors.
const char* const kSpuriousTinygltfErrors[] = {
    "'inverseBindMatrices' property is missing in Skin.",
    "'node' property is missing.",
    "`node` field is missing in animation.channels.target",
};

std::vector<std::string> nonEmptyLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    if (!line.empty()) out.push_back(line);
  }
  return out;
}

bool spurious(const std::string& errorLine) {
  return std::any_of(std::begin(kSpuriousTinygltfErrors), std::end(kSpuriousTinygltfErrors),
                     [&](const char* s) { return errorLine == s; });
}

// Filesystem callbacks for tinygltf: only regular files, never larger than kMaxFileBytes. The
// defaults open whatever a uri names. Corpus invalid/tinygltf/issue-416.gltf has an image uri
// that decodes to a name starting with a NUL byte, so the C file API opens the base directory
// and tinygltf allocates its "size", 2^63 bytes, and crashes (the no-op image loader alone does
// not prevent that: the file is read before any image is decoded). A FIFO or /dev/zero named
// by a uri would block or exhaust memory the same way.
bool regularFileExists(const std::string& path, void*) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

bool readRegularFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    *err = "not a regular file";
    return false;
  }
  const uintmax_t size = fs::file_size(path, ec);
  if (ec || size > kMaxFileBytes) {
    *err = ec ? ec.message() : "larger than 2 GiB";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  out->resize(size);
  if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) {
    *err = "read failed";
    return false;
  }
  return true;
}

// radview draws no textures, so images are never decoded (the bytes are not even looked at).
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

// "2.0" -> {2, 0}; false unless the string is exactly <digits>.<digits> (spec: asset.version pattern).
bool parseVersion(const std::string& text, int& major, int& minor) {
  const size_t dot = text.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == text.size() || dot > 4 || text.size() - dot > 5) return false;
  for (size_t i = 0; i < text.size(); ++i)
    if (i != dot && !std::isdigit(static_cast<unsigned char>(text[i]))) return false;
  major = std::stoi(text.substr(0, dot));
  minor = std::stoi(text.substr(dot + 1));
  return true;
}

void checkVersion(const std::string& path, const tinygltf::Asset& asset) {
  int major = 0, minor = 0;
  if (asset.version.empty()) throw Error(path, "asset.version is missing");
  if (!parseVersion(asset.version, major, minor))
    throw Error(path, "asset.version \"" + asset.version + "\" is not of the form <major>.<minor>");
  if (major != 2) throw Error(path, "asset.version is " + asset.version + "; radview reads glTF 2.x only");
  if (asset.minVersion.empty()) return;
  int minMajor = 0, minMinor = 0;
  if (!parseVersion(asset.minVersion, minMajor, minMinor))
    throw Error(path, "asset.minVersion \"" + asset.minVersion + "\" is not of the form <major>.<minor>");
  if (std::make_pair(minMajor, minMinor) > std::make_pair(major, minor))
    throw Error(path, "asset.minVersion " + asset.minVersion + " is greater than asset.version " + asset.version);
  if (std::make_pair(minMajor, minMinor) > std::make_pair(2, 0))
    throw Error(path, "the file requires glTF " + asset.minVersion + " (asset.minVersion); radview reads glTF 2.0");
}

void checkRequiredExtensions(const std::string& path, const tinygltf::Model& model) {
  for (const std::string& name : model.extensionsRequired) {
    const bool supported = std::any_of(std::begin(kSupportedRequiredExtensions), std::end(kSupportedRequiredExtensions),
                                       [&](const char* s) { return name == s; });
    if (!supported) throw Error(path, "the file requires extension " + name + ", which radview does not support");
  }
}

// --- accessor decoding -------------------------------------------------------------------

struct ComponentType {
  int code = 0;  // TINYGLTF_COMPONENT_TYPE_*
  unsigned bit = 0;
  uint64_t size = 0;
  const char* name = "";
};

const ComponentType kComponentTypes[] = {
    {TINYGLTF_COMPONENT_TYPE_BYTE, kByte, 1, "BYTE"},
    {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, kUnsignedByte, 1, "UNSIGNED_BYTE"},
    {TINYGLTF_COMPONENT_TYPE_SHORT, kShort, 2, "SHORT"},
    {TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, kUnsignedShort, 2, "UNSIGNED_SHORT"},
    {TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, kUnsignedInt, 4, "UNSIGNED_INT"},
    {TINYGLTF_COMPONENT_TYPE_FLOAT, kFloat, 4, "FLOAT"},
};

const ComponentType* findComponentType(int code) {
  for (const ComponentType& t : kComponentTypes)
    if (t.code == code) return &t;
  return nullptr;
}

std::string allowedTypeNames(unsigned bits) {
  std::string out;
  for (const ComponentType& t : kComponentTypes)
    if (bits & t.bit) out += (out.empty() ? "" : ", ") + std::string(t.name);
  return out;
}

int componentsOf(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;  // matrices: never read by radview
  }
}

const char* typeName(int components) {
  switch (components) {
    case 1:
      return "SCALAR";
    case 2:
      return "VEC2";
    case 3:
      return "VEC3";
    case 4:
      return "VEC4";
    default:
      return "a matrix type";
  }
}

// One component; normalized integers as the glTF 2.0 spec decodes them (e.g. max(c / 127, -1)).
double decodeComponent(const unsigned char* p, int code, bool normalized) {
  switch (code) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      int8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      uint8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? v / 255.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

// Reports the first problem found in one accessor as "<what>: accessor N: <problem>".
class AccessorReader {
 public:
  AccessorReader(const std::string& path, const tinygltf::Model& model, int index, const AccessorRequest& request)
      : path_(path), model_(model), index_(index), request_(request) {}

  std::vector<double> read() {
    if (index_ < 0 || size_t(index_) >= model_.accessors.size())
      throw Error(path_, request_.what + ": accessor " + std::to_string(index_) + " does not exist (the file has " +
                             std::to_string(model_.accessors.size()) + " accessors)");
    const tinygltf::Accessor& accessor = model_.accessors[size_t(index_)];
    const ComponentType* type = checkFormat(accessor);
    const uint64_t components = uint64_t(request_.components);
    const uint64_t elementSize = components * type->size;
    const uint64_t count = accessor.count;
    if (count == 0) fail("count is 0 (glTF requires at least 1)");
    if (count > kMaxAccessorElements)
      fail("count " + std::to_string(count) + ", more than radview's limit of " + std::to_string(kMaxAccessorElements) +
           " elements");

    std::vector<double> values;
    if (accessor.bufferView < 0) {
      if (accessor.byteOffset != 0) fail("has a byteOffset but no bufferView");
      if (count > kMaxZeroFilledCount)
        fail("has no bufferView and a count of " + std::to_string(count) + ", more than radview's limit of " +
             std::to_string(kMaxZeroFilledCount) + " for such accessors");
      values.assign(count * components, 0.0);  // the spec: no bufferView means zeros
    } else {
      if (accessor.byteOffset % type->size != 0)
        fail("byteOffset " + std::to_string(accessor.byteOffset) + " is not a multiple of the component size");
      const tinygltf::BufferView& view = bufferView(accessor.bufferView, "");
      uint64_t stride = view.byteStride;
      if (stride == 0) {
        stride = elementSize;
      } else {
        if (stride < 4 || stride > 252 || stride % 4 != 0)
          fail("bufferView " + std::to_string(accessor.bufferView) + " has byteStride " + std::to_string(stride) +
               " (glTF allows multiples of 4 from 4 to 252)");
        if (stride < elementSize)
          fail("bufferView " + std::to_string(accessor.bufferView) + " has byteStride " + std::to_string(stride) +
               ", smaller than the element size " + std::to_string(elementSize));
      }
      if ((view.byteOffset + accessor.byteOffset) % type->size != 0)
        fail("data does not start at a multiple of the component size within its buffer");
      const unsigned char* base =
          viewBytes(view, accessor.bufferView, accessor.byteOffset, stride, count, elementSize, "");
      values.resize(count * components);
      for (uint64_t i = 0; i < count; ++i)
        for (uint64_t c = 0; c < components; ++c)
          values[i * components + c] =
              decodeComponent(base + i * stride + c * type->size, type->code, accessor.normalized);
    }
    if (accessor.sparse.isSparse) applySparse(accessor, *type, values);
    if (type->code == TINYGLTF_COMPONENT_TYPE_FLOAT)
      for (size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i])) fail("element " + std::to_string(i / components) + " is not finite");
    return values;
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    throw Error(path_, request_.what + ": accessor " + std::to_string(index_) + ": " + problem);
  }

  const ComponentType* checkFormat(const tinygltf::Accessor& accessor) const {
    const int components = componentsOf(accessor.type);
    if (components != request_.components)
      fail(std::string("is ") + typeName(components) + ", expected " + typeName(request_.components));
    const ComponentType* type = findComponentType(accessor.componentType);
    if (type == nullptr || !(type->bit & request_.componentTypes)) {
      const std::string name = type ? type->name : std::to_string(accessor.componentType);
      fail("component type " + name + " is not allowed here (allowed: " + allowedTypeNames(request_.componentTypes) +
           ")");
    }
    if (accessor.normalized) {
      if (type->code == TINYGLTF_COMPONENT_TYPE_FLOAT || type->code == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(std::string("is normalized, which glTF does not allow for ") + type->name);
      if (!request_.normalizedAllowed) fail("is normalized, which is not allowed here");
    }
    return type;
  }

  const tinygltf::BufferView& bufferView(int viewIndex, const std::string& role) const {
    if (viewIndex < 0 || size_t(viewIndex) >= model_.bufferViews.size())
      fail(role + "bufferView " + std::to_string(viewIndex) + " does not exist (the file has " +
           std::to_string(model_.bufferViews.size()) + " bufferViews)");
    const tinygltf::BufferView& view = model_.bufferViews[size_t(viewIndex)];
    if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
      fail(role + "bufferView " + std::to_string(viewIndex) + " refers to buffer " + std::to_string(view.buffer) +
           ", which does not exist (the file has " + std::to_string(model_.buffers.size()) + " buffers)");
    return view;
  }

  // The bytes of `count` elements of `elementSize` bytes, `stride` apart, starting `offset`
  // bytes into the view; fails unless all of them lie inside the view and the view inside its
  // buffer. Every sum and product is checked: the inputs come straight from the file.
  const unsigned char* viewBytes(const tinygltf::BufferView& view, int viewIndex, uint64_t offset, uint64_t stride,
                                 uint64_t count, uint64_t elementSize, const std::string& role) const {
    const std::vector<unsigned char>& data = model_.buffers[size_t(view.buffer)].data;
    const std::string viewName = role + "bufferView " + std::to_string(viewIndex);
    uint64_t viewEnd = 0;
    if (view.byteLength == 0) fail(viewName + " has byteLength 0");
    if (__builtin_add_overflow(uint64_t(view.byteOffset), uint64_t(view.byteLength), &viewEnd) || viewEnd > data.size())
      fail(viewName + " (byteOffset " + std::to_string(view.byteOffset) + ", byteLength " +
           std::to_string(view.byteLength) + ") runs past the end of buffer " + std::to_string(view.buffer) + " (" +
           std::to_string(data.size()) + " bytes)");
    uint64_t span = 0, end = 0;
    if (__builtin_mul_overflow(stride, count - 1, &span) || __builtin_add_overflow(span, elementSize, &span) ||
        __builtin_add_overflow(span, offset, &end) || end > view.byteLength)
      fail(std::to_string(count) + " elements of " + std::to_string(elementSize) + " bytes, stride " +
           std::to_string(stride) + ", from byte " + std::to_string(offset) + " run past the end of " + viewName +
           " (byteLength " + std::to_string(view.byteLength) + ")");
    return data.data() + view.byteOffset + offset;
  }

  // Sparse storage: `count` (index, value) pairs override elements of the base data.
  void applySparse(const tinygltf::Accessor& accessor, const ComponentType& type, std::vector<double>& values) const {
    const auto& sparse = accessor.sparse;
    const uint64_t components = uint64_t(request_.components);
    if (sparse.count < 1 || uint64_t(sparse.count) > accessor.count)
      fail("sparse.count " + std::to_string(sparse.count) + " is not in [1, " + std::to_string(accessor.count) + "]");
    const uint64_t count = uint64_t(sparse.count);
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) fail("sparse byteOffset is negative");

    const ComponentType* indexType = findComponentType(sparse.indices.componentType);
    if (indexType == nullptr || !(indexType->bit & kUnsignedIntegerTypes))
      fail("sparse.indices.componentType " + std::to_string(sparse.indices.componentType) +
           " is not UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    const tinygltf::BufferView& indexView = bufferView(sparse.indices.bufferView, "sparse.indices ");
    const tinygltf::BufferView& valueView = bufferView(sparse.values.bufferView, "sparse.values ");
    if (indexView.byteStride != 0 || valueView.byteStride != 0)
      fail("a bufferView of sparse data has a byteStride, which glTF forbids");
    const uint64_t elementSize = components * type.size;
    const unsigned char* indexBytes =
        viewBytes(indexView, sparse.indices.bufferView, uint64_t(sparse.indices.byteOffset), indexType->size, count,
                  indexType->size, "sparse.indices ");
    const unsigned char* valueBytes = viewBytes(valueView, sparse.values.bufferView, uint64_t(sparse.values.byteOffset),
                                                elementSize, count, elementSize, "sparse.values ");
    double previous = -1.0;
    for (uint64_t i = 0; i < count; ++i) {
      const double target = decodeComponent(indexBytes + i * indexType->size, indexType->code, false);
      if (target <= previous) fail("sparse indices are not strictly increasing at sparse element " + std::to_string(i));
      if (target >= double(accessor.count))
        fail("sparse index " + std::to_string(uint64_t(target)) + " is past the count " +
             std::to_string(accessor.count));
      previous = target;
      for (uint64_t c = 0; c < components; ++c)
        values[uint64_t(target) * components + c] =
            decodeComponent(valueBytes + i * elementSize + c * type.size, type.code, accessor.normalized);
    }
  }

  const std::string& path_;
  const tinygltf::Model& model_;
  int index_;
  const AccessorRequest& request_;
};

}  // namespace

GltfDocument::GltfDocument(const std::string& path) : path_(path), model_(std::make_unique<tinygltf::Model>()) {
  checkInputFile(path, "a glTF file");
  const std::string ext = lowerExtension(path);
  if (ext != ".gltf" && ext != ".glb")
    throw Error(path, "unknown file type \"" + ext + "\" (radview reads .gltf and .glb)");

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&skipImage, nullptr);
  loader.SetFsCallbacks(
      {&regularFileExists, &tinygltf::ExpandFilePath, &readRegularFile, &tinygltf::WriteWholeFile, nullptr});
  std::string err, warn;
  bool ok = false;
  try {
    ok = ext == ".glb" ? loader.LoadBinaryFromFile(model_.get(), &err, &warn, path)
                       : loader.LoadASCIIFromFile(model_.get(), &err, &warn, path);
  } catch (const std::exception& e) {
    // tinygltf 2.7.0 indexes some malformed inputs with vector::at (a GLB whose buffer 0 has
    // byteLength 0 beside a BIN chunk: tests/fuzz/regressions/gltf/): it is still a bad file.
    throw Error(path, std::string("tinygltf stopped on malformed content (") + e.what() + ")");
  }
  if (!ok) throw Error(path, err.empty() ? "tinygltf could not parse the file" : oneLine(err));
  // tinygltf 2.7.0 can also report success while setting an error (corpus glb/unaligned_chunk.glb):
  // that is a failure too, unless every error line is one of the known spurious ones.
  const std::vector<std::string> errors = nonEmptyLines(err);
  if (!std::all_of(errors.begin(), errors.end(), spurious)) throw Error(path, oneLine(err));
  checkVersion(path, model_->asset);
  checkRequiredExtensions(path, *model_);

  for (const std::string& line : errors) warnings_.push_back("tinygltf: " + line);
  for (const std::string& line : nonEmptyLines(warn)) warnings_.push_back(line);
  if (!model_->images.empty())
    warnings_.push_back(std::to_string(model_->images.size()) + " image(s) not decoded: radview draws no textures");
}

GltfDocument::~GltfDocument() = default;
GltfDocument::GltfDocument(GltfDocument&&) noexcept = default;
GltfDocument& GltfDocument::operator=(GltfDocument&&) noexcept = default;

bool GltfDocument::usesExtension(const std::string& name) const {
  const auto& used = model_->extensionsUsed;
  return std::find(used.begin(), used.end(), name) != used.end();
}

std::vector<double> GltfDocument::readAccessor(int index, const AccessorRequest& request) const {
  return AccessorReader(path_, *model_, index, request).read();
}

std::vector<Vec3> GltfDocument::readVec3(int index, const AccessorRequest& request) const {
  RADVIEW_CHECK(request.components == 3);
  const std::vector<double> values = readAccessor(index, request);
  std::vector<Vec3> out(values.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) out[i] = Vec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
  return out;
}

std::vector<uint32_t> GltfDocument::readUnsigned(int index, const std::string& what, uint64_t limit,
                                                 Restart restart) const {
  const std::vector<double> values = readAccessor(index, {what, 1, kUnsignedIntegerTypes, false});
  // The primitive-restart value is the largest value of the component type.
  const ComponentType* type = findComponentType(model_->accessors[size_t(index)].componentType);
  const double restartValue = std::ldexp(1.0, int(8 * type->size)) - 1.0;
  std::vector<uint32_t> out(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    const bool isRestart = restart == Restart::Forbidden && values[i] == restartValue;
    if (isRestart || values[i] >= double(limit)) {
      const std::string where = what + ": accessor " + std::to_string(index) + ": element " + std::to_string(i);
      if (isRestart)
        throw Error(path_, where + " is the primitive-restart value " + std::to_string(uint64_t(restartValue)) +
                               ", which glTF forbids in indices");
      throw Error(path_, where + " is " + std::to_string(uint64_t(values[i])) + ", out of range (must be < " +
                             std::to_string(limit) + ")");
    }
    out[i] = uint32_t(values[i]);
  }
  return out;
}

}  // namespace radview
