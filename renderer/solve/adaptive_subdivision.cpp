#include "solve/adaptive_subdivision.h"

#include "geom/polygon.h"
#include "mesh/solution_file.h"
#include "mesh/topology.h"
#include "solve/interpolation_error.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace radview {

namespace {

uint64_t edgeKey(uint32_t a, uint32_t b) { return uint64_t(std::min(a, b)) << 32 | std::max(a, b); }

double longestEdge(const std::vector<Vec3>& corners) {
  double longest = 0.0;
  for (size_t i = 0; i < corners.size(); ++i)
    longest = std::max(longest, glm::distance(corners[i], corners[(i + 1) % corners.size()]));
  return longest;
}

// Elements a split of this one makes: 4 for a triangle, one quad per corner otherwise.
size_t childCount(const Element& element) { return element.corners.size() == 3 ? 4 : element.corners.size(); }

}  // namespace

double displayValue(const Rgb& B, double toneMapScale) {
  const double Y = 0.2126 * B.r + 0.7152 * B.g + 0.0722 * B.b;
  const double v = std::clamp(Y * toneMapScale, 0.0, 1.0);
  // The sRGB transfer a display applies: equal steps of it are about equally visible.
  const double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return 255.0 * encoded;
}

std::vector<uint32_t> elementsToSplit(const RadiosityMesh& valued, const SubdivisionCriteria& criteria) {
  const double scale = toneMapScale(valued);
  const bool forViews = !criteria.views.empty();
  const std::vector<uint32_t> pixels = viewedPixels(valued, criteria.views);
  const std::vector<double> relativeErrors = criteria.relativeError > 0.0
                                                 ? relativeInterpolationErrors(valued, 0.01 / scale)
                                                 : std::vector<double>(valued.elements.size(), 0.0);
  std::vector<std::pair<double, uint32_t>> candidates;  // (priority, element)
  for (uint32_t e = 0; e < valued.elements.size(); ++e) {
    const Element& element = valued.elements[e];
    if (forViews && pixels[e] == 0) continue;
    if (valued.materials[element.material].isEmitter() || !MeshRefiner::canSplit(valued, e)) continue;
    if (longestEdge(valued.cornerPositions(e)) < 2.0 * criteria.minElementSize) continue;
    double lo = INFINITY, hi = -INFINITY;
    for (const auto* list : {&element.corners, &element.midEdge})
      for (uint32_t node : *list) {
        const double v = displayValue(valued.nodes[node].B, scale);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    double excess = (hi - lo) / criteria.tolerance;
    if (criteria.relativeError > 0.0) excess = std::max(excess, relativeErrors[e] / criteria.relativeError);
    if (excess > 1.0) candidates.push_back({forViews ? excess * excess * double(pixels[e]) : excess, e});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const auto& x, const auto& y) { return x.first != y.first ? x.first > y.first : x.second < y.second; });
  std::vector<uint32_t> chosen;
  size_t count = valued.elements.size();
  for (const auto& [priority, e] : candidates) {
    const size_t grown = count + childCount(valued.elements[e]) - 1;
    if (grown > criteria.maxElements) break;
    count = grown;
    chosen.push_back(e);
  }
  return chosen;
}

std::vector<uint32_t> unbalancedElements(const RadiosityMesh& mesh, const SubdivisionCriteria& criteria) {
  const MeshTopology topology(mesh);
  const std::vector<uint32_t> pixels = viewedPixels(mesh, criteria.views);
  // (element, edge) -> the first T-vertex position on it; a second position marks it.
  std::unordered_map<uint64_t, uint32_t> firstPosition;
  std::vector<char> unbalanced(mesh.elements.size(), 0);
  for (const TVertex& t : topology.tVertices()) {
    const uint32_t position = topology.positionId(t.node);
    const auto [at, added] = firstPosition.emplace(uint64_t(t.element) << 32 | t.edge, position);
    if (!added && at->second != position) unbalanced[t.element] = 1;
  }
  std::vector<uint32_t> chosen;
  size_t count = mesh.elements.size();
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    if (!unbalanced[e] || !MeshRefiner::canSplit(mesh, e)) continue;
    if (!criteria.views.empty() && pixels[e] == 0) continue;
    if (mesh.materials[mesh.elements[e].material].isEmitter()) continue;
    if (longestEdge(mesh.cornerPositions(e)) < 2.0 * criteria.minElementSize) continue;
    const size_t grown = count + childCount(mesh.elements[e]) - 1;
    if (grown > criteria.maxElements) break;
    count = grown;
    chosen.push_back(e);
  }
  return chosen;
}

MeshRefiner::MeshRefiner(const RadiosityMesh& mesh) {
  for (const Element& element : mesh.elements)
    for (size_t i = 0; i < element.midEdge.size(); ++i)
      mid_[edgeKey(element.corners[i], element.corners[(i + 1) % element.corners.size()])] = element.midEdge[i];
  if (mesh.discontinuities.empty()) return;
  // Tags by every side's own node pair: across a C-1 edge the sides have different nodes, and
  // whichever side is split must find the tag.
  const MeshTopology topology(mesh);
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    const std::vector<uint32_t>& corners = mesh.elements[e].corners;
    for (uint32_t i = 0; i < corners.size(); ++i) {
      const Continuity order = topology.edges()[topology.edgeIndex(e, i)].continuity;
      if (order != Continuity::C1) tagOrder_[edgeKey(corners[i], corners[(i + 1) % corners.size()])] = order;
    }
  }
}

bool MeshRefiner::canSplit(const RadiosityMesh& mesh, uint32_t element) {
  return mesh.elements[element].corners.size() == 3 || isConvex(mesh.cornerPositions(element));
}

uint32_t MeshRefiner::newNode(RadiosityMesh& mesh, const Vec3& position) {
  Node node;
  node.position = position;
  mesh.nodes.push_back(node);
  return uint32_t(mesh.nodes.size() - 1);
}

uint32_t MeshRefiner::midNode(RadiosityMesh& mesh, uint32_t a, uint32_t b) {
  const auto [it, added] = mid_.emplace(edgeKey(a, b), 0);
  if (added) it->second = newNode(mesh, 0.5 * (mesh.nodes[a].position + mesh.nodes[b].position));
  return it->second;
}

void MeshRefiner::makeQuadratic(RadiosityMesh& mesh) {
  for (Element& element : mesh.elements) {
    if (!element.midEdge.empty()) continue;
    const size_t n = element.corners.size();
    for (size_t i = 0; i < n; ++i)
      element.midEdge.push_back(midNode(mesh, element.corners[i], element.corners[(i + 1) % n]));
  }
}

size_t MeshRefiner::split(RadiosityMesh& mesh, const std::vector<uint32_t>& elements, std::vector<uint32_t>& parentOf) {
  std::unordered_set<uint32_t> done;
  for (uint32_t e : elements) {
    if (!canSplit(mesh, e) || !done.insert(e).second) continue;
    const Element parent = mesh.elements[e];
    const std::vector<uint32_t>& c = parent.corners;
    const size_t n = c.size();
    std::vector<uint32_t> m(n);
    for (size_t i = 0; i < n; ++i) {
      m[i] = midNode(mesh, c[i], c[(i + 1) % n]);
      const auto tag = tagOrder_.find(edgeKey(c[i], c[(i + 1) % n]));
      if (tag != tagOrder_.end()) {
        const Continuity order = tag->second;  // the halves of a tagged edge keep its tag
        tagOrder_[edgeKey(c[i], m[i])] = order;
        tagOrder_[edgeKey(m[i], c[(i + 1) % n])] = order;
      }
    }
    std::vector<std::vector<uint32_t>> children;
    if (n == 3) {
      children = {{c[0], m[0], m[2]}, {m[0], c[1], m[1]}, {m[2], m[1], c[2]}, {m[0], m[1], m[2]}};
    } else {
      // A quad's bilinear centre is its corners' mean; a larger polygon's, its area centroid.
      Vec3 centre(0.0);
      for (uint32_t node : c) centre += mesh.nodes[node].position;
      centre = n == 4 ? centre / 4.0 : centroid(mesh.cornerPositions(e));
      const uint32_t o = newNode(mesh, centre);
      for (size_t i = 0; i < n; ++i) children.push_back({c[i], m[i], o, m[(i + n - 1) % n]});
    }
    for (size_t k = 0; k < children.size(); ++k) {
      Element child;
      child.corners = children[k];
      child.material = parent.material;
      child.surface = parent.surface;
      if (parent.order() == ElementOrder::Quadratic)
        for (size_t i = 0; i < child.corners.size(); ++i)
          child.midEdge.push_back(midNode(mesh, child.corners[i], child.corners[(i + 1) % child.corners.size()]));
      if (k == 0) {
        mesh.elements[e] = std::move(child);
      } else {
        mesh.elements.push_back(std::move(child));
        parentOf.push_back(e);
      }
    }
  }
  if (!done.empty()) retag(mesh);
  return done.size();
}

// The mesh's tag list again, from tagOrder_: every element edge that is tagged, once per node
// pair, in element order.
void MeshRefiner::retag(RadiosityMesh& mesh) const {
  if (tagOrder_.empty()) return;
  mesh.discontinuities.clear();
  std::unordered_set<uint64_t> emitted;
  for (const Element& element : mesh.elements) {
    const size_t n = element.corners.size();
    for (size_t i = 0; i < n; ++i) {
      const uint32_t a = element.corners[i], b = element.corners[(i + 1) % n];
      const auto tag = tagOrder_.find(edgeKey(a, b));
      if (tag != tagOrder_.end() && emitted.insert(tag->first).second)
        mesh.discontinuities.push_back({a, b, tag->second});
    }
  }
}

}  // namespace radview
