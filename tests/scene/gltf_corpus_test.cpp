// loadFile over every model of the third-party glTF corpus (shared/corpus/gltf): valid files
// load or are refused with a reason; invalid files are refused, or load with at least one
// warning saying what radview left out. Nothing may crash or hang, which is worth running once
// in a build with -fsanitize=address,undefined: the corpus is full of hostile byte ranges.
#include "import/load_file.h"

#include "core/error.h"
#include "scene/gltf_document.h"
#include "tests/shared_corpus.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace radview {
namespace {

namespace fs = std::filesystem;

enum class Outcome { Loaded, LoadedWithWarnings, Refused };

struct Result {
  std::string file;  // relative to the corpus root
  Outcome outcome;
  std::string detail;  // the error, or the first warning
};

std::vector<std::string> modelFiles(const fs::path& root) {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb")) files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

Result load(const fs::path& root, const std::string& file) {
  Result r{fs::relative(file, root).string(), Outcome::Refused, ""};
  try {
    const LoadedFile loaded = loadFile(file);
    r.outcome = loaded.warnings.empty() ? Outcome::Loaded : Outcome::LoadedWithWarnings;
    if (!loaded.warnings.empty()) r.detail = loaded.warnings.front();
  } catch (const Error& e) {
    // The message is "<file>: <reason>"; keep the reason.
    const std::string message = e.what();
    r.detail = message.rfind(file + ": ", 0) == 0 ? message.substr(file.size() + 2) : "(no file prefix) " + message;
  }
  return r;
}

// The first problem the validated reader finds in the file's data, whether the scene uses it
// or not: every accessor (matrices aside) with any component type, then each primitive's
// POSITION and indices with their own rules. Most of the validator's files damage data that no
// scene node uses, which loadFile rightly never reads; this reads it anyway, to exercise the
// reader on valid data (it must accept all of it) and on damaged data. Empty if none.
std::string readerProblem(const std::string& file) {
  const unsigned anyType = kByte | kUnsignedByte | kShort | kUnsignedShort | kUnsignedInt | kFloat;
  try {
    const GltfDocument document(file);
    const tinygltf::Model& model = document.model();
    for (size_t a = 0; a < model.accessors.size(); ++a) {
      const int type = model.accessors[a].type;
      const int components = type == TINYGLTF_TYPE_SCALAR ? 1 : type >= 2 && type <= 4 ? type : 0;
      if (components > 0) document.readAccessor(int(a), {"accessor check", components, anyType, true});
    }
    const bool quantized = document.usesExtension("KHR_mesh_quantization");
    for (size_t m = 0; m < model.meshes.size(); ++m)
      for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
        const tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) continue;
        const std::string what = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
        const unsigned types = quantized ? kFloat | kByte | kUnsignedByte | kShort | kUnsignedShort : kFloat;
        const size_t count = document.readVec3(position->second, {what + " POSITION", 3, types, quantized}).size();
        if (primitive.indices >= 0)
          document.readUnsigned(primitive.indices, what + " indices", count, GltfDocument::Restart::Forbidden);
      }
  } catch (const Error& e) {
    const std::string message = e.what();
    return message.substr(std::min(message.size(), file.size() + 2));
  }
  return "";
}

const char* name(Outcome o) {
  switch (o) {
    case Outcome::Loaded:
      return "loaded";
    case Outcome::LoadedWithWarnings:
      return "loaded+warn";
    case Outcome::Refused:
      return "refused";
  }
  return "?";
}

TEST(SharedCorpusGltf, EveryModelLoadsOrIsRefusedClearly) {
  const fs::path root = RADVIEW_CORPUS_DIR;
  RADVIEW_REQUIRE_SHARED_CORPUS(root);
  std::map<std::string, std::map<Outcome, int>> counts;  // "valid" / "invalid" -> outcome -> files
  std::map<std::string, int> readerRefused;              // "valid" / "invalid" -> files
  for (const std::string& file : modelFiles(root)) {
    const Result r = load(root, file);
    const std::string set = r.file.substr(0, r.file.find('/'));
    ++counts[set][r.outcome];
    std::cout << "[corpus] " << name(r.outcome) << "\t" << r.file << (r.detail.empty() ? "" : "\t") << r.detail << "\n";
    if (r.outcome != Outcome::Refused || r.detail.rfind("no triangles to show", 0) == 0) {
      const std::string problem = readerProblem(file);
      if (!problem.empty()) {
        ++readerRefused[set];
        std::cout << "[corpus]   reader refuses\t" << r.file << "\t" << problem << "\n";
      }
      if (set == "valid") {
        EXPECT_EQ(problem, "") << r.file << ": the validated reader refuses valid data";
      }
    }
    if (set == "valid" && r.outcome == Outcome::Refused) {
      EXPECT_FALSE(r.detail.empty()) << r.file << " refused without a reason";
      EXPECT_EQ(r.detail.rfind("(no file prefix)", 0), std::string::npos) << r.file << ": " << r.detail;
    }
    if (set == "invalid") {
      EXPECT_NE(r.outcome, Outcome::Loaded) << r.file << " is invalid but loaded without a warning";
      if (r.outcome == Outcome::Refused) {
        EXPECT_EQ(r.detail.rfind("(no file prefix)", 0), std::string::npos) << r.file << ": " << r.detail;
      }
    }
  }
  std::cout << "[corpus] valid: " << counts["valid"][Outcome::Loaded] + counts["valid"][Outcome::LoadedWithWarnings]
            << " loaded (" << counts["valid"][Outcome::LoadedWithWarnings] << " with warnings), "
            << counts["valid"][Outcome::Refused] << " refused with a reason\n"
            << "[corpus] invalid: " << counts["invalid"][Outcome::Refused] << " refused, "
            << counts["invalid"][Outcome::LoadedWithWarnings] << " loaded with a warning, "
            << counts["invalid"][Outcome::Loaded] << " loaded silently\n"
            << "[corpus] data (all accessors and primitives, in a scene or not) refused by the validated reader: "
            << readerRefused["valid"] << " valid, " << readerRefused["invalid"] << " invalid files\n";
  EXPECT_GT(counts["valid"][Outcome::Loaded] + counts["valid"][Outcome::LoadedWithWarnings], 0);
}

}  // namespace
}  // namespace radview
