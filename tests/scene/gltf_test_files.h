#pragma once
// glTF files written by the tests themselves: a builder of small models (tinygltf's), a fixture
// with a folder to write them into and the error a load gives, and the check that an error
// names the file and the problem on one line.
#include "scene/gltf_import.h"

#include "core/error.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace radview::test {

// Builds a glTF model in memory: one buffer, one bufferView per accessor.
struct GltfBuilder {
  tinygltf::Model model;

  GltfBuilder() {
    model.buffers.emplace_back();
    model.asset.version = "2.0";
  }

  int view(const void* data, size_t size, size_t stride = 0) {
    std::vector<unsigned char>& bytes = model.buffers[0].data;
    bytes.resize((bytes.size() + 3) / 4 * 4);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = bytes.size();
    v.byteLength = size;
    v.byteStride = stride;
    bytes.insert(bytes.end(), static_cast<const unsigned char*>(data), static_cast<const unsigned char*>(data) + size);
    model.bufferViews.push_back(v);
    return int(model.bufferViews.size()) - 1;
  }
  int accessor(int bufferView, int componentType, int type, size_t count) {
    tinygltf::Accessor a;
    a.bufferView = bufferView;
    a.componentType = componentType;
    a.type = type;
    a.count = count;
    model.accessors.push_back(a);
    return int(model.accessors.size()) - 1;
  }
  int positions(const std::vector<float>& xyz) {
    return accessor(view(xyz.data(), xyz.size() * 4), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                    xyz.size() / 3);
  }
  template <typename T>
  int indices(const std::vector<T>& values) {
    const int type = sizeof(T) == 1   ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE
                     : sizeof(T) == 2 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                                      : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    return accessor(view(values.data(), values.size() * sizeof(T)), type, TINYGLTF_TYPE_SCALAR, values.size());
  }
  int mesh(int positionAccessor, int indexAccessor = -1, int mode = TINYGLTF_MODE_TRIANGLES, int material = -1) {
    tinygltf::Primitive p;
    p.attributes["POSITION"] = positionAccessor;
    p.indices = indexAccessor;
    p.mode = mode;
    p.material = material;
    tinygltf::Mesh m;
    m.primitives.push_back(p);
    model.meshes.push_back(m);
    return int(model.meshes.size()) - 1;
  }
  int node(int meshIndex, std::vector<int> children = {}) {
    tinygltf::Node n;
    n.mesh = meshIndex;
    n.children = std::move(children);
    model.nodes.push_back(n);
    return int(model.nodes.size()) - 1;
  }
  int material(std::vector<double> baseColor, std::vector<double> emissive, double strength = -1.0) {
    tinygltf::Material m;
    m.name = "m" + std::to_string(model.materials.size());
    m.pbrMetallicRoughness.baseColorFactor = std::move(baseColor);
    m.emissiveFactor = std::move(emissive);
    if (strength >= 0.0) {
      m.extensions["KHR_materials_emissive_strength"] =
          tinygltf::Value(tinygltf::Value::Object{{"emissiveStrength", tinygltf::Value(strength)}});
      model.extensionsUsed.push_back("KHR_materials_emissive_strength");
    }
    model.materials.push_back(m);
    return int(model.materials.size()) - 1;
  }
  // A unit right triangle in z = 0 facing +Z, as a whole file: node 0 -> mesh 0.
  static GltfBuilder triangle() {
    GltfBuilder b;
    b.node(b.mesh(b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0})));
    return b;
  }

  void write(const std::string& path, bool binary = false) const {
    tinygltf::TinyGLTF writer;
    ASSERT_TRUE(writer.WriteGltfSceneToFile(&model, path, false, true, true, binary)) << path;
  }
};

class GltfImportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("radview_gltf_import_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  Scene import(const GltfBuilder& builder, std::vector<std::string>* warningsOut = nullptr) {
    const std::string file = path("scene.gltf");
    builder.write(file);
    const GltfDocument document(file);
    std::vector<std::string> warnings = document.warnings();
    Scene scene = importScene(document, warnings);
    if (warningsOut) *warningsOut = warnings;
    return scene;
  }

  // The Error message of opening and importing `file`; empty (a test failure) if none.
  std::string errorOf(const std::string& file) {
    try {
      const GltfDocument document(file);
      std::vector<std::string> warnings;
      importScene(document, warnings);
    } catch (const Error& e) {
      return e.what();
    }
    ADD_FAILURE() << file << " was accepted";
    return "";
  }
  std::string errorOf(const GltfBuilder& builder, const std::string& name = "bad.gltf") {
    builder.write(path(name));
    return errorOf(path(name));
  }
  // A triangle written as raw JSON, for what tinygltf's writer cannot express (it drops
  // minVersion and writes byteOffset as an int); its data in tri.bin.
  std::string rawTriangle(const std::string& name, const std::string& asset, const std::string& accessor) {
    const std::vector<float> xyz{0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::ofstream(path("tri.bin"), std::ios::binary).write(reinterpret_cast<const char*>(xyz.data()), 36);
    std::ofstream(path(name)) << R"({"asset": )" << asset << R"(,
      "buffers": [{"uri": "tri.bin", "byteLength": 36}], "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", )"
                              << accessor << R"(}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}]})";
    return path(name);
  }
  void writeBytes(const std::string& name, const std::string& bytes) {
    std::ofstream(path(name), std::ios::binary) << bytes;
  }

  std::filesystem::path dir_;
};

// The message names the file and states the problem.
#define EXPECT_ERROR_NAMES(message, file, problem)                     \
  do {                                                                 \
    const std::string m_ = (message);                                  \
    EXPECT_NE(m_.find(file), std::string::npos) << m_;                 \
    EXPECT_NE(m_.find(problem), std::string::npos) << m_;              \
    EXPECT_EQ(m_.find('\n'), std::string::npos) << "one line: " << m_; \
  } while (0)

}  // namespace radview::test
