// Other tools' meshes as radiosity meshes (import/load_file.h): the same mesh as PLY (float and
// 8-bit), OBJ and glTF COLOR_0 gives each node its value at the node; quads stay quads; the
// colour conventions, the optional readings and every refusal the issue names.
#include "import/load_file.h"

#include "core/display_transform.h"
#include "import/ply_mesh.h"
#include "import/ply_writer.h"
#include "interp/interpolant.h"
#include "tests/error_message.h"
#include "tests/import/same_mesh_formats.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <filesystem>

namespace radview {
namespace {

using test::errorOf;
using test::SameMesh;
using test::writeTestFile;

// The node of `mesh` at `position` whose value is nearest to `expected` (two share each
// position along the jump).
const Node& nodeAt(const RadiosityMesh& mesh, const Vec3& position, const Rgb& expected) {
  const Node* best = nullptr;
  for (const Node& n : mesh.nodes)
    if (n.position == position && (!best || glm::length(n.B - expected) < glm::length(best->B - expected))) best = &n;
  EXPECT_NE(best, nullptr) << "no node at " << position.x << "," << position.y;
  return *best;
}

// Every element's interpolant, evaluated at each of its corners, gives that corner's node value:
// what `radview sample` prints for those points.
void expectNodeValuesAtNodes(const RadiosityMesh& mesh, Method method) {
  const auto interpolant = makeInterpolant(mesh, method);
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (uint32_t n : mesh.elements[e].corners) {
      const Rgb B = interpolant->evaluate(e, mesh.nodes[n].position).B;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(B[k], mesh.nodes[n].B[k], 1e-12) << "element " << e << " node " << n;
    }
}

TEST(ImportMesh, FloatPlyKeepsEveryValueExactlyHdrIncluded) {
  const SameMesh same;
  const LoadedFile file = loadFile(writeTestFile("float.ply", same.plyFloatAscii()));
  EXPECT_TRUE(file.isSolution);
  ASSERT_EQ(file.mesh.nodes.size(), 8u);  // the two positions along the jump hold two nodes each
  ASSERT_EQ(file.mesh.elements.size(), 2u);
  for (const Element& e : file.mesh.elements) EXPECT_EQ(e.corners.size(), 4u);  // quads stay quads
  for (size_t v = 0; v < 8; ++v) EXPECT_EQ(file.mesh.nodes[v].B, same.B[v]) << v;
  EXPECT_EQ(file.valueSource, "vertex properties red green blue (float), taken as linear radiosity as they are");
  EXPECT_NE(file.gatherRefusal, "");
  expectNodeValuesAtNodes(file.mesh, Method::CloughTocher);
  expectNodeValuesAtNodes(file.mesh, Method::Bilinear);
}

TEST(ImportMesh, EightBitPlyIsSrgbDecodedWithinItsQuantisation) {
  const SameMesh same;
  const LoadedFile file = loadFile(writeTestFile("byte.ply", same.plyByteBigEndian()));
  ASSERT_EQ(file.mesh.nodes.size(), 8u);
  for (size_t v = 0; v < 8; ++v)
    for (int k = 0; k < 3; ++k) {
      const double stored = std::min(same.B[v][k], 1.0);  // 8 bits cannot hold more than 1
      EXPECT_EQ(file.mesh.nodes[v].B[k], SameMesh::fromByte(SameMesh::byteOf(stored))) << v;
      // Within half an 8-bit step of the display value; the sRGB decoding's slope is below 2.3.
      EXPECT_NEAR(file.mesh.nodes[v].B[k], stored, 0.5 / 255.0 * 2.3) << v;
    }
  EXPECT_EQ(file.valueSource, "vertex properties red green blue (uchar), scaled to [0, 1] and sRGB-decoded to linear");
  expectNodeValuesAtNodes(file.mesh, Method::CloughTocher);

  ImportOptions linear;
  linear.colours = ColourEncoding::Linear;
  const LoadedFile asLinear = loadFile(writeTestFile("byte.ply", same.plyByteBigEndian()), linear);
  EXPECT_EQ(asLinear.mesh.nodes[0].B.r, SameMesh::byteOf(0.25) / 255.0);
}

TEST(ImportMesh, ObjJoinsCornersButNotTheJump) {
  const SameMesh same;
  const LoadedFile file = loadFile(writeTestFile("mesh.obj", same.obj()));
  ASSERT_EQ(file.mesh.nodes.size(), 8u);
  ASSERT_EQ(file.mesh.elements.size(), 2u);
  for (const Element& e : file.mesh.elements) EXPECT_EQ(e.corners.size(), 4u);
  for (size_t v = 0; v < 8; ++v) EXPECT_EQ(nodeAt(file.mesh, same.positions[v], same.B[v]).B, same.B[v]) << v;
  expectNodeValuesAtNodes(file.mesh, Method::CloughTocher);
  ImportOptions srgb;
  srgb.colours = ColourEncoding::Srgb;
  const LoadedFile decoded = loadFile(writeTestFile("mesh.obj", same.obj()), srgb);
  EXPECT_EQ(nodeAt(decoded.mesh, same.positions[0], Rgb(0.0)).B.r, srgbDecode(0.25));
}

TEST(ImportMesh, GltfColour0WithoutEmitterIsAMeshWithEmitterAScene) {
  const SameMesh same;
  const LoadedFile file = loadFile(writeTestFile("colour.gltf", same.gltfColour0()));
  EXPECT_TRUE(file.isSolution);
  ASSERT_EQ(file.mesh.nodes.size(), 8u);
  EXPECT_EQ(file.mesh.elements.size(), 4u);  // glTF stores triangles
  for (size_t v = 0; v < 8; ++v) EXPECT_EQ(file.mesh.nodes[v].B, same.B[v]) << v;
  EXPECT_EQ(file.valueSource, "COLOR_0 (float), linear as glTF defines it");
  expectNodeValuesAtNodes(file.mesh, Method::CloughTocher);

  const std::string lit = writeTestFile("colour_lit.gltf", same.gltfColour0(true));
  const LoadedFile scene = loadFile(lit);
  EXPECT_FALSE(scene.isSolution);
  EXPECT_NE(std::find_if(scene.warnings.begin(), scene.warnings.end(),
                         [](const std::string& w) { return w.find("COLOR_0 read as a factor of rho") == 0; }),
            scene.warnings.end());
  // In a scene COLOR_0 multiplies rho (glTF): each triangle gets its corners' mean, in 8-bit
  // steps. Triangle (0, 1, 2) has the mean red (0.25 + 0.5 + 1) / 3.
  bool found = false;
  for (const Polygon& polygon : scene.scene.polygons)
    if (polygon.vertices.size() == 3 && polygon.vertices[0] == Vec3(0, 0, 0) && polygon.vertices[1] == Vec3(1, 0, 0)) {
      found = true;
      EXPECT_EQ(scene.scene.materials[size_t(polygon.material)].rho.r, std::round(255.0 * 1.75 / 3.0) / 255.0);
    }
  EXPECT_TRUE(found);
  ImportOptions asSolution;
  asSolution.readAs = ReadAs::Solution;
  EXPECT_TRUE(loadFile(lit, asSolution).isSolution);
  ImportOptions asScene;
  asScene.readAs = ReadAs::Scene;
  EXPECT_FALSE(loadFile(writeTestFile("colour.gltf", same.gltfColour0()), asScene).isSolution);
  EXPECT_EQ(errorOf([&] { loadFile(RADVIEW_SOURCE_DIR "/assets/cornell_box.gltf", asSolution); }),
            RADVIEW_SOURCE_DIR "/assets/cornell_box.gltf: --read-as solution: no primitive has COLOR_0");
}

std::string plyWithVertices(const std::string& vertexProperties, const std::string& vertices,
                            const std::string& faces = "3 0 1 2\n", const std::string& more = "") {
  const size_t vertexCount = std::count(vertices.begin(), vertices.end(), '\n');
  const size_t faceCount = std::count(faces.begin(), faces.end(), '\n');
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertexCount) +
         "\nproperty float x\nproperty float y\nproperty float z\n" + vertexProperties + "element face " +
         std::to_string(faceCount) + "\nproperty list uchar int vertex_indices\n" + more + "end_header\n" + vertices +
         faces;
}

ImportedMesh readPlyText(const std::string& text, const ImportOptions& options = {}) {
  return readPlyMesh(writeTestFile("case.ply", text), options);
}

TEST(ImportMesh, GreyScalarsAndNamedProperties) {
  const std::string vertices = "0 0 0 0.5 9\n1 0 0 1.5 9\n0 1 0 2.5 9\n";
  const ImportedMesh grey = readPlyText(plyWithVertices("property float radiosity\nproperty float other\n", vertices));
  EXPECT_EQ(grey.mesh.nodes[1].B, Rgb(1.5));
  EXPECT_EQ(grey.valueSource, "vertex property radiosity (float, grey), taken as linear radiosity as they are");
  ImportOptions named;
  named.valueProperty = "other";
  EXPECT_EQ(
      readPlyText(plyWithVertices("property float radiosity\nproperty float other\n", vertices), named).mesh.nodes[0].B,
      Rgb(9.0));
  named.valueProperty = "missing";
  EXPECT_NE(errorOf([&] {
              readPlyText(plyWithVertices("property float radiosity\nproperty float other\n", vertices), named);
            }).find("vertex has no property missing (it has: x y z radiosity other)"),
            std::string::npos);
}

TEST(ImportMesh, EdgeElementCarriesDiscontinuities) {
  const std::string vertices = "0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n1 1 0 1 1 1\n";
  const std::string rgb = "property float red\nproperty float green\nproperty float blue\n";
  const std::string edges = "element edge 2\nproperty int vertex1\nproperty int vertex2\nproperty char continuity\n";
  const std::string text = plyWithVertices(rgb, vertices, "3 0 1 2\n3 1 3 2\n", edges) + "1 2 -1\n0 1 0\n";
  const ImportedMesh m = readPlyText(text);
  ASSERT_EQ(m.mesh.discontinuities.size(), 2u);
  EXPECT_EQ(m.mesh.discontinuities[0].order, Continuity::Cm1);
  EXPECT_EQ(m.mesh.discontinuities[1].a, 0u);
  EXPECT_EQ(m.mesh.discontinuities[1].order, Continuity::C0);
  EXPECT_NE(errorOf([&] {
              readPlyText(plyWithVertices(rgb, vertices, "3 0 1 2\n3 1 3 2\n", edges) + "1 2 5\n0 1 0\n");
            }).find("edge 0: continuity 5"),
            std::string::npos);
}

TEST(ImportMesh, BadFacesAndValuesAreRefusedNamingTheFault) {
  const std::string rgb = "property float red\nproperty float green\nproperty float blue\n";
  const std::string ok = "0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n";
  auto error = [&](const std::string& text) {
    const std::string message = errorOf([&] { readPlyText(text); });
    const std::string prefix = writeTestFile("case.ply", "") + ": ";
    return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : "(no file prefix) " + message;
  };
  EXPECT_EQ(error(plyWithVertices(rgb, ok, "3 0 1 7\n")), "face 0 refers to vertex 7; the file has 3");
  EXPECT_EQ(error(plyWithVertices(rgb, ok, "3 0 1 -1\n")), "face 0 refers to vertex -1; the file has 3");
  EXPECT_EQ(error(plyWithVertices(rgb, ok, "3 0 1 1\n")), "face 0 uses vertex 1 twice");
  EXPECT_EQ(error(plyWithVertices(rgb, ok, "2 0 1\n")), "face 0 has 2 vertices (a face needs at least 3)");
  EXPECT_EQ(error(plyWithVertices(rgb, "0 0 0 1 nan 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n")),
            "vertex 0: green is nan, not a finite number");
  EXPECT_EQ(error(plyWithVertices(rgb, "0 0 0 1 1 1\n1 0 inf 1 1 1\n0 1 0 1 1 1\n")),
            "vertex 1: its position is not finite");
  EXPECT_EQ(error(plyWithVertices(rgb, "0 0 0 1 1 1\n1 0 0 1 1 1\n2 0 0 1 1 1\n")), "every face has zero area");
  EXPECT_EQ(error(plyWithVertices("property char red\nproperty char green\nproperty char blue\n",
                                  "0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n")),
            "vertex property red is char: radview reads values stored as float, double or unsigned integers");
  EXPECT_EQ(error(plyWithVertices("", "0 0 0\n1 0 0\n0 1 0\n")),
            "no per-vertex values: the vertex element has x y z; radview reads B from red green blue (or r g b, "
            "diffuse_red ...), a scalar named radiosity or B, or one named with --value-property");
  EXPECT_EQ(error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                  "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n0 0 0 1 2 3\n"),
            "no faces: a point cloud of 1 vertices (radview shows radiosity on surfaces)");

  // A zero-area face among good ones is dropped, and said so.
  const ImportedMesh dropped =
      readPlyText(plyWithVertices(rgb, "0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n2 0 0 1 1 1\n", "3 0 1 2\n3 0 1 3\n"));
  EXPECT_EQ(dropped.mesh.elements.size(), 1u);
  EXPECT_EQ(dropped.mesh.nodes.size(), 3u);
  EXPECT_EQ(dropped.warnings,
            (std::vector<std::string>{"1 zero-area face(s) dropped", "1 vertex(es) that no face uses left out"}));
}

TEST(ImportMesh, ATagOnlyADroppedFaceHadGoesWithIt) {
  const std::string rgb = "property float red\nproperty float green\nproperty float blue\n";
  const std::string vertices = "0 0 0 1 1 1\n1 0 0 1 1 1\n2 0 0 1 1 1\n0 1 0 1 1 1\n1 1 0 1 1 1\n";
  const std::string edges = "element edge 1\nproperty int vertex1\nproperty int vertex2\nproperty char continuity\n";
  const ImportedMesh m = readPlyText(plyWithVertices(rgb, vertices, "3 0 1 2\n3 0 4 3\n3 1 2 4\n", edges) + "0 1 -1\n");
  EXPECT_EQ(m.mesh.elements.size(), 2u);
  EXPECT_TRUE(m.mesh.discontinuities.empty());
  EXPECT_EQ(m.warnings, (std::vector<std::string>{"1 zero-area face(s) dropped",
                                                  "1 tagged edge(s) that no kept face has left out"}));
}

TEST(ImportMesh, ObjFacesWhoseCornersJoinAreDropped) {
  // Vertices 1 and 4 share a position and a colour: one node, and the first face has no area.
  const std::string obj = "v 0 0 0 1 1 1\nv 1 0 0 1 1 1\nv 0 1 0 1 1 1\nv 0 0 0 1 1 1\nf 1 2 4\nf 1 2 3\n";
  const LoadedFile file = loadFile(writeTestFile("joined.obj", obj));
  EXPECT_EQ(file.mesh.elements.size(), 1u);
  EXPECT_EQ(file.mesh.nodes.size(), 3u);
  EXPECT_EQ(file.warnings,
            (std::vector<std::string>{"1 face(s) with two corners at one vertex (one position and colour) dropped"}));
}

TEST(ImportMesh, ExportedPlyReadsBackToTheSameMesh) {
  const RadiosityMesh written = loadFile(RADVIEW_SOURCE_DIR "/assets/discontinuities.gltf").mesh;
  const std::string path = writeTestFile("exported.ply", "");
  writePly(written, path);
  const RadiosityMesh read = loadFile(path).mesh;
  ASSERT_EQ(read.nodes.size(), written.nodes.size());
  for (size_t n = 0; n < read.nodes.size(); ++n) {
    EXPECT_EQ(read.nodes[n].position, written.nodes[n].position) << n;
    EXPECT_EQ(read.nodes[n].B, written.nodes[n].B) << n;
  }
  ASSERT_EQ(read.elements.size(), written.elements.size());
  for (size_t e = 0; e < read.elements.size(); ++e) EXPECT_EQ(read.elements[e].corners, written.elements[e].corners);
  std::vector<std::tuple<uint32_t, uint32_t, int>> tagsWritten, tagsRead;
  for (const DiscontinuityEdge& d : written.discontinuities)
    if (d.order != Continuity::C1) tagsWritten.emplace_back(d.a, d.b, int(d.order));
  for (const DiscontinuityEdge& d : read.discontinuities) tagsRead.emplace_back(d.a, d.b, int(d.order));
  EXPECT_EQ(tagsRead, tagsWritten);
  EXPECT_FALSE(tagsRead.empty());

  // Same values under the C1 interpolant, which reads the tags, at points inside the elements.
  const auto before = makeInterpolant(written, Method::CloughTocher);
  const auto after = makeInterpolant(read, Method::CloughTocher);
  for (uint32_t e = 0; e < read.elements.size(); ++e) {
    Vec3 centroid(0.0);
    for (uint32_t n : read.elements[e].corners)
      centroid += read.nodes[n].position / double(read.elements[e].corners.size());
    EXPECT_EQ(after->evaluate(e, centroid).B, before->evaluate(e, centroid).B) << e;
  }

  RadiosityMesh withGradients = written;
  withGradients.hasGradients = true;
  withGradients.nodes[3].gradient[1] = Vec3(0.5, -2.0, 0.0);
  writePly(withGradients, path);
  const RadiosityMesh gradientsRead = loadFile(path).mesh;
  EXPECT_TRUE(gradientsRead.hasGradients);
  EXPECT_EQ(gradientsRead.nodes[3].gradient[1], Vec3(0.5, -2.0, 0.0));
}

TEST(ImportMesh, AssumedReflectanceAndEmittersLetTheGatherRun) {
  const SameMesh same;
  const std::string path = writeTestFile("float.ply", same.plyFloatAscii());
  EXPECT_EQ(loadFile(path).gatherRefusal,
            "this file gives no reflectance and no emitter, which the final gather and the path tracer need (give "
            "--rho R,G,B and "
            "--emitters-above LUMINANCE)");
  ImportOptions options;
  options.rho = Rgb(0.5, 0.6, 0.7);
  EXPECT_EQ(
      loadFile(path, options).gatherRefusal,
      "this file gives no emitter, which the final gather and the path tracer need (give --emitters-above LUMINANCE)");
  options.emittersAbove = 0.15;  // the right quad's nodes all reach it, the left quad's do not
  const LoadedFile lit = loadFile(path, options);
  EXPECT_EQ(lit.gatherRefusal, "");
  const Material& left = lit.mesh.materials[size_t(lit.mesh.elements[0].material)];
  const Material& right = lit.mesh.materials[size_t(lit.mesh.elements[1].material)];
  EXPECT_FALSE(left.isEmitter());
  EXPECT_EQ(left.rho, Rgb(0.5, 0.6, 0.7));
  EXPECT_EQ(right.E, lit.mesh.meanB(1));
  EXPECT_EQ(right.rho, Rgb(0.5, 0.6, 0.7));
  options.emittersAbove = 50.0;
  EXPECT_NE(errorOf([&] { loadFile(path, options); }).find("--emitters-above 50.000000: no element has all its nodes"),
            std::string::npos);

  // glTF materials carry rho; only the emitter is missing.
  EXPECT_EQ(
      loadFile(writeTestFile("colour.gltf", same.gltfColour0())).gatherRefusal,
      "this file gives no emitter, which the final gather and the path tracer need (give --emitters-above LUMINANCE)");
}

TEST(ImportMesh, ObjMaterialLibraryGivesReflectanceAndEmission) {
  const std::string obj =
      "mtllib box.mtl\nv 0 0 0 1 1 1\nv 1 0 0 1 1 1\nv 1 1 0 1 1 1\nv 0 1 0 1 1 1\n"
      "v 0 0 1 0.5 0.5 0.5\nv 1 0 1 0.5 0.5 0.5\nv 1 1 1 0.5 0.5 0.5\n"
      "usemtl light\nf 1 2 3 4\nusemtl wall\nf 5 6 7\n";
  const std::string path = writeTestFile("box.obj", obj);
  std::filesystem::remove(std::filesystem::path(path).parent_path() / "box.mtl");  // from an earlier run
  EXPECT_EQ(loadFile(path).gatherRefusal,
            "this file gives no reflectance and no emitter, which the final gather and the path tracer need (give "
            "--rho R,G,B and "
            "--emitters-above LUMINANCE)");  // box.mtl is not there yet
  writeTestFile("box.mtl", "newmtl light\nKd 0.1 0.2 0.3\nKe 5 5 5\nnewmtl wall\nKd 0.7 0.6 0.5\n");
  const LoadedFile file = loadFile(path);
  EXPECT_EQ(file.gatherRefusal, "");
  ASSERT_EQ(file.mesh.elements.size(), 2u);
  const Material& light = file.mesh.materials[size_t(file.mesh.elements[0].material)];
  const Material& wall = file.mesh.materials[size_t(file.mesh.elements[1].material)];
  EXPECT_EQ(light.name, "light");
  EXPECT_EQ(light.E, Rgb(5.0));
  EXPECT_NEAR(light.rho.g, 0.2, 1e-7);
  EXPECT_EQ(wall.name, "wall");
  EXPECT_FALSE(wall.isEmitter());
  EXPECT_NEAR(wall.rho.r, 0.7, 1e-7);
}

// Another reader than radview's own takes the exported file as a PLY of the same mesh: Assimp's
// PLY importer (what MeshLab-like tools see: the positions, the faces as polygons, the colours).
TEST(ImportMesh, ExportedPlyReadsInAnotherReader) {
  const RadiosityMesh written = loadFile(RADVIEW_SOURCE_DIR "/assets/t_vertices.gltf").mesh;  // quads
  const std::string path = writeTestFile("exported.ply", "");
  writePly(written, path);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  ASSERT_EQ(scene->mNumMeshes, 1u);
  const aiMesh& mesh = *scene->mMeshes[0];
  ASSERT_EQ(mesh.mNumVertices, written.nodes.size());
  ASSERT_EQ(mesh.mNumFaces, written.elements.size());
  ASSERT_TRUE(mesh.HasVertexColors(0));
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    EXPECT_EQ(mesh.mVertices[v].x, float(written.nodes[v].position.x)) << v;
    EXPECT_EQ(mesh.mColors[0][v].g, float(written.nodes[v].B.g)) << v;
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    ASSERT_EQ(mesh.mFaces[f].mNumIndices, written.elements[f].corners.size()) << f;
    for (unsigned k = 0; k < mesh.mFaces[f].mNumIndices; ++k)
      EXPECT_EQ(mesh.mFaces[f].mIndices[k], written.elements[f].corners[k]) << f;
  }
}

}  // namespace
}  // namespace radview
