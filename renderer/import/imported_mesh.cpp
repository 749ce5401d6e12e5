#include "import/imported_mesh.h"

#include "core/display_transform.h"
#include "core/error.h"
#include "geom/polygon.h"

#include <algorithm>
#include <limits>
#include <string>
#include <unordered_set>

namespace radview {

namespace {

// As the glTF import's test for degenerate triangles: twice the area below this fraction of
// the longest edge squared is zero up to rounding (repeated or collinear corners).
constexpr double kDegenerateRatio = 1e-10;

bool zeroArea(const std::vector<Vec3>& corners) {
  double longest2 = 0.0;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Vec3 d = corners[(i + 1) % corners.size()] - corners[i];
    longest2 = std::max(longest2, glm::dot(d, d));
  }
  return !(glm::length(newellNormal(corners)) > kDegenerateRatio * longest2);
}

}  // namespace

double linearValue(double stored, double integerMax, ColourEncoding encoding) {
  const bool integer = integerMax > 0.0;
  const double value = integer ? stored / integerMax : stored;
  const bool decode = encoding == ColourEncoding::Srgb || (encoding == ColourEncoding::Auto && integer);
  return decode ? srgbDecode(value) : value;
}

std::string conversionName(bool integerStored, ColourEncoding encoding) {
  const bool decode = encoding == ColourEncoding::Srgb || (encoding == ColourEncoding::Auto && integerStored);
  if (decode) return integerStored ? "scaled to [0, 1] and sRGB-decoded to linear" : "sRGB-decoded to linear";
  return integerStored ? "scaled to [0, 1], taken as linear" : "taken as linear radiosity as they are";
}

Material unknownMaterial() { return {"not in the file (rho and E unknown)", Rgb(0.0), Rgb(0.0)}; }

void finishImportedMesh(ImportedMesh& imported, const std::string& path) {
  RadiosityMesh& mesh = imported.mesh;
  const size_t before = mesh.elements.size();
  std::vector<Element> kept;
  kept.reserve(before);
  for (size_t e = 0; e < before; ++e)
    if (!zeroArea(mesh.cornerPositions(e))) kept.push_back(std::move(mesh.elements[e]));
  mesh.elements = std::move(kept);
  if (mesh.elements.size() < before)
    imported.warnings.push_back(std::to_string(before - mesh.elements.size()) + " zero-area face(s) dropped");
  if (mesh.elements.empty()) throw Error(path, before == 0 ? "no faces to show" : "every face has zero area");

  // Used nodes keep the file's order.
  constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> renumbered(mesh.nodes.size(), kUnused);
  for (const Element& element : mesh.elements)
    for (uint32_t n : element.corners) renumbered[n] = 0;
  std::vector<Node> nodes;
  for (size_t n = 0; n < mesh.nodes.size(); ++n)
    if (renumbered[n] != kUnused) {
      renumbered[n] = uint32_t(nodes.size());
      nodes.push_back(mesh.nodes[n]);
    }
  for (Element& element : mesh.elements)
    for (uint32_t& n : element.corners) n = renumbered[n];
  if (nodes.size() < mesh.nodes.size())
    imported.warnings.push_back(std::to_string(mesh.nodes.size() - nodes.size()) +
                                " vertex(es) that no face uses left out");
  // Tags stay on the edges of kept elements; one that only a dropped face had goes with it.
  std::unordered_set<uint64_t> elementEdges;
  auto key = [](uint32_t a, uint32_t b) { return uint64_t(std::min(a, b)) << 32 | std::max(a, b); };
  for (const Element& element : mesh.elements)
    for (size_t i = 0; i < element.corners.size(); ++i)
      elementEdges.insert(key(element.corners[i], element.corners[(i + 1) % element.corners.size()]));
  std::vector<DiscontinuityEdge> edges;
  size_t droppedTags = 0;
  for (const DiscontinuityEdge& d : mesh.discontinuities) {
    const bool kept = renumbered[d.a] != kUnused && renumbered[d.b] != kUnused &&
                      elementEdges.count(key(renumbered[d.a], renumbered[d.b]));
    if (kept)
      edges.push_back({renumbered[d.a], renumbered[d.b], d.order});
    else
      ++droppedTags;
  }
  if (droppedTags > 0)
    imported.warnings.push_back(std::to_string(droppedTags) + " tagged edge(s) that no kept face has left out");
  mesh.nodes = std::move(nodes);
  mesh.discontinuities = std::move(edges);
  validateMesh(mesh, path);
}

void assumeMaterials(ImportedMesh& imported, const ImportOptions& options, const std::string& path) {
  RadiosityMesh& mesh = imported.mesh;
  if (options.rho)
    for (Material& m : mesh.materials) {
      m.rho = *options.rho;
      m.name += " (rho from --rho)";
    }
  if (options.emittersAbove) {
    // One emitting material per material the emitters had, E the emitters' mean nodal B.
    const double threshold = *options.emittersAbove;
    const size_t materials = mesh.materials.size();
    std::vector<int> emitterOf(materials, -1);
    std::vector<Rgb> sum;
    std::vector<size_t> count;
    double brightest = 0.0;
    for (size_t e = 0; e < mesh.elements.size(); ++e) {
      Element& element = mesh.elements[e];
      bool emits = true;
      for (uint32_t n : element.corners) {
        brightest = std::max(brightest, luminance(mesh.nodes[n].B));
        emits = emits && luminance(mesh.nodes[n].B) >= threshold;
      }
      if (!emits) continue;
      int& emitter = emitterOf[size_t(element.material)];
      if (emitter < 0) {
        Material m = mesh.materials[size_t(element.material)];
        m.name += " (emits: --emitters-above)";
        emitter = int(mesh.materials.size());
        mesh.materials.push_back(m);
        sum.resize(mesh.materials.size(), Rgb(0.0));
        count.resize(mesh.materials.size(), 0);
      }
      sum[size_t(emitter)] += mesh.meanB(e);
      ++count[size_t(emitter)];
      element.material = emitter;
    }
    if (mesh.materials.size() == materials)
      throw Error(path, "--emitters-above " + std::to_string(threshold) +
                            ": no element has all its nodes that bright (the brightest node's luminance is " +
                            std::to_string(brightest) + ")");
    for (size_t m = materials; m < mesh.materials.size(); ++m) mesh.materials[m].E = sum[m] / double(count[m]);
  }
  const bool reflectance = imported.reflectanceFromFile || options.rho.has_value();
  const bool emitters =
      std::any_of(mesh.materials.begin(), mesh.materials.end(), [](const Material& m) { return m.isEmitter(); });
  imported.gatherRefusal.clear();
  if (reflectance && emitters) return;
  const std::string lacking = !reflectance && !emitters ? "no reflectance and no emitter"
                              : !reflectance            ? "no reflectance"
                                                        : "no emitter";
  const std::string give = !reflectance && !emitters ? "--rho R,G,B and --emitters-above LUMINANCE"
                           : !reflectance            ? "--rho R,G,B"
                                                     : "--emitters-above LUMINANCE";
  imported.gatherRefusal = "this file gives " + lacking + ", which the final gather and the path tracer need (give " + give + ")";
}

}  // namespace radview
