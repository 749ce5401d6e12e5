// The fuzz targets' bodies in the ordinary test build: every input that once crashed a
// target (tests/fuzz/regressions/) is replayed, and the seeds the targets start from are
// checked to be what they claim (valid files open, meshes survive their byte encoding).
#include "import/load_file.h"
#include "mesh/topology.h"
#include "tests/fuzz/fuzz_inputs.h"
#include "tests/fuzz/mesh_bytes.h"
#include "tests/shared_corpus.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

namespace radview {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<fs::path> filesIn(const fs::path& directory) {
  std::vector<fs::path> files;
  if (fs::is_directory(directory))
    for (const fs::directory_entry& entry : fs::directory_iterator(directory))
      if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

const fs::path kSource = RADVIEW_SOURCE_DIR;

// Every input that once crashed a target, replayed through the target's body: it must no
// longer crash, abort or report, and must take the way tests/fuzz/regressions/outcomes.txt
// records for it (refused or opened). A kept input missing from that list fails the test, as
// does a listed one that is gone.
TEST(FuzzRegressions, EveryKeptInputHasItsRecordedOutcome) {
  const fs::path folder = kSource / "tests/fuzz/regressions";
  const std::map<std::string, bool (*)(const uint8_t*, size_t)> bodies = {
      {"gltf", fuzz::openGltfBytes}, {"mesh", fuzz::buildMeshBytes}, {"import", fuzz::importMeshBytes},
      {"npy", fuzz::parseNpyBytes}};
  std::map<std::string, bool> recorded;  // "target/file" -> opened
  std::ifstream list(folder / "outcomes.txt");
  ASSERT_TRUE(list) << "no " << (folder / "outcomes.txt");
  for (std::string line; std::getline(list, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string input, outcome;
    fields >> input >> outcome;
    ASSERT_TRUE(outcome == "refused" || outcome == "opened") << "outcomes.txt: " << line;
    recorded[input] = outcome == "opened";
  }
  size_t replayed = 0;
  for (const auto& [target, body] : bodies)
    for (const fs::path& file : filesIn(folder / target)) {
      const std::string input = target + "/" + file.filename().string();
      SCOPED_TRACE(input);
      ASSERT_EQ(recorded.count(input), 1u) << "a kept input with no outcome in outcomes.txt";
      const std::vector<uint8_t> bytes = readBytes(file);
      EXPECT_EQ(body(bytes.data(), bytes.size()), recorded[input]);
      ++replayed;
    }
  EXPECT_EQ(replayed, recorded.size()) << "outcomes.txt lists an input that is not kept";
}

// The importer target's seeds include the shared corpus; its files must take the same way
// through the target as through loadFile.
TEST(SharedCorpusFuzzSeeds, OtherToolsMeshesTakeTheImporterTarget) {
  const fs::path corpus = kSource / "../shared/corpus/mesh-colours";
  RADVIEW_REQUIRE_SHARED_CORPUS(corpus);
  for (const char* name : {"trimesh_quadknot.obj", "draco_test_pos_color_big_endian.ply", "trimesh_reference.ply"}) {
    SCOPED_TRACE(name);
    const std::vector<uint8_t> bytes = readBytes(corpus / name);
    EXPECT_TRUE(fuzz::importMeshBytes(bytes.data(), bytes.size()));
  }
  for (const char* name : {"trimesh_fuze_ascii.ply", "trimesh_nancolor.obj", "assimp_points.ply"}) {
    SCOPED_TRACE(name);
    const std::vector<uint8_t> bytes = readBytes(corpus / name);
    EXPECT_FALSE(fuzz::importMeshBytes(bytes.data(), bytes.size()));
  }
}

TEST(FuzzSeeds, BundledFilesOpenThroughTheGltfTargetAndBadOnesAreRefused) {
  for (const fs::path& file : filesIn(kSource / "assets")) {
    if (file.extension() != ".gltf") continue;
    SCOPED_TRACE(file.string());
    const std::vector<uint8_t> bytes = readBytes(file);
    EXPECT_TRUE(fuzz::openGltfBytes(bytes.data(), bytes.size()));
  }
  for (const char* bad : {"tests/data/bad_accessor.gltf", "tests/data/truncated.glb"}) {
    SCOPED_TRACE(bad);
    const std::vector<uint8_t> bytes = readBytes(kSource / bad);
    EXPECT_FALSE(fuzz::openGltfBytes(bytes.data(), bytes.size()));
  }
}

// The .npy target's seeds are numpy's own files: each must parse.
TEST(FuzzSeeds, NumpysArraysParseThroughTheNpyTarget) {
  int seeds = 0;
  for (const fs::path& file : filesIn(kSource / "tests/data")) {
    if (file.extension() != ".npy") continue;
    SCOPED_TRACE(file.string());
    const std::vector<uint8_t> bytes = readBytes(file);
    EXPECT_EQ(fuzz::parseNpyBytes(bytes.data(), bytes.size()), file.filename() != "not_numpy.npy");
    ++seeds;
  }
  EXPECT_GE(seeds, 3);
}

// The mesh target's seeds are the bundled solutions in its byte encoding: they must decode to
// valid meshes of the same structure, or the fuzzer would start from nothing.
TEST(FuzzSeeds, BundledSolutionsSurviveTheMeshEncoding) {
  int solutions = 0;
  for (const fs::path& file : filesIn(kSource / "assets")) {
    if (file.extension() != ".gltf") continue;
    const LoadedFile loaded = loadFile(file.string());
    if (!loaded.isSolution) continue;
    SCOPED_TRACE(file.string());
    ++solutions;
    const RadiosityMesh& original = loaded.mesh;
    const std::vector<uint8_t> bytes = fuzz::encodeMesh(original);
    const RadiosityMesh decoded = fuzz::decodeMesh(bytes.data(), bytes.size());
    ASSERT_NO_THROW(validateMesh(decoded, file.string()));
    EXPECT_EQ(decoded.nodes.size(), original.nodes.size());
    ASSERT_EQ(decoded.elements.size(), original.elements.size());
    for (size_t e = 0; e < original.elements.size(); ++e) {
      EXPECT_EQ(decoded.elements[e].corners, original.elements[e].corners);
      EXPECT_EQ(decoded.elements[e].midEdge, original.elements[e].midEdge);
    }
    ASSERT_EQ(decoded.discontinuities.size(), original.discontinuities.size());
    for (size_t d = 0; d < original.discontinuities.size(); ++d)
      EXPECT_EQ(decoded.discontinuities[d].order, original.discontinuities[d].order);
    // B to three significant digits of its largest channel, over 16 decades.
    for (size_t n = 0; n < original.nodes.size(); ++n) {
      const Rgb& b = original.nodes[n].B;
      const double largest = std::max({b.r, b.g, b.b});
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(decoded.nodes[n].B[c], b[c], 5e-3 * largest + 1e-8);
    }
    EXPECT_TRUE(fuzz::buildMeshBytes(bytes.data(), bytes.size()));
  }
  EXPECT_GE(solutions, 4);
}

}  // namespace
}  // namespace radview
