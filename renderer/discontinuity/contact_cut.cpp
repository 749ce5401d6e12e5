#include "discontinuity/contact_cut.h"

#include "discontinuity/discontinuity_events.h"
#include "geom/polygon.h"
#include "trace/ray_caster.h"

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <tuple>

namespace radview {

namespace {

// Cuts one convex element (its corner nodes) by the line a-b of the polygon's plane frame, when
// the line passes through its interior: vertices within `tolerance` of the line go to both
// pieces, and an edge it crosses gets a node there, one per (edge, line) whoever asks.
class LineCutter {
 public:
  LineCutter(RadiosityMesh& mesh, const PlaneFrame& frame, double tolerance)
      : mesh_(mesh), frame_(frame), tolerance_(tolerance) {}

  std::vector<std::vector<uint32_t>> cut(const std::vector<uint32_t>& corners, const Vec2& a, const Vec2& b,
                                         size_t line) {
    const Vec2 direction = glm::normalize(b - a);
    std::vector<double> d;
    for (uint32_t node : corners) {
      const Vec2 p = frame_.project(mesh_.nodes[node].position) - a;
      d.push_back(direction.x * p.y - direction.y * p.x);
    }
    const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
    if (*lo >= -tolerance_ || *hi <= tolerance_) return {corners};
    std::vector<uint32_t> left, right;
    for (size_t i = 0; i < corners.size(); ++i) {
      const size_t j = (i + 1) % corners.size();
      if (d[i] >= -tolerance_) left.push_back(corners[i]);
      if (d[i] <= tolerance_) right.push_back(corners[i]);
      if ((d[i] > tolerance_ && d[j] < -tolerance_) || (d[i] < -tolerance_ && d[j] > tolerance_)) {
        const uint32_t node = nodeOnEdge(corners[i], d[i], corners[j], d[j], line);
        left.push_back(node);
        right.push_back(node);
      }
    }
    return {left, right};
  }

 private:
  // From the edge's lower-numbered end, so that both elements on the edge get the same bits.
  uint32_t nodeOnEdge(uint32_t p, double dp, uint32_t q, double dq, size_t line) {
    if (p > q) std::swap(p, q), std::swap(dp, dq);
    const auto [it, added] = made_.emplace(std::make_tuple(p, q, line), uint32_t(mesh_.nodes.size()));
    if (added) {
      Node node;
      const Vec3& x = mesh_.nodes[p].position;
      node.position = x + (dp / (dp - dq)) * (mesh_.nodes[q].position - x);
      mesh_.nodes.push_back(node);
    }
    return it->second;
  }

  RadiosityMesh& mesh_;
  const PlaneFrame& frame_;
  double tolerance_;
  std::map<std::tuple<uint32_t, uint32_t, size_t>, uint32_t> made_;
};

}  // namespace

RadiosityMesh cutAtContacts(const Scene& scene, RadiosityMesh mesh) {
  const std::vector<std::vector<EventSegment>> events = findContacts(scene);
  std::vector<Element> cut;
  std::vector<PlaneFrame> frames(scene.polygons.size());
  std::vector<std::unique_ptr<LineCutter>> cutters(scene.polygons.size());
  for (size_t p = 0; p < scene.polygons.size(); ++p) {
    if (events[p].empty()) continue;
    frames[p] = planeFrame(scene.polygons[p].vertices);
    Bounds bounds;
    for (const Vec3& v : scene.polygons[p].vertices) bounds.extend(v);
    cutters[p] = std::make_unique<LineCutter>(mesh, frames[p], kEventTolerance * bounds.diagonal());
  }
  for (const Element& element : mesh.elements) {
    std::vector<std::vector<uint32_t>> pieces = {element.corners};
    const int s = element.surface;
    if (s >= 0 && size_t(s) < cutters.size() && cutters[s])
      for (size_t k = 0; k < events[s].size(); ++k) {
        const EventSegment& contact = events[s][k];
        std::vector<std::vector<uint32_t>> next;
        for (const std::vector<uint32_t>& piece : pieces) {
          // Only where the segment itself reaches the piece: its line may run on through
          // elements beside the contact.
          std::vector<Vec2> outline;
          for (uint32_t node : piece) outline.push_back(frames[s].project(mesh.nodes[node].position));
          if (clipSegmentToPolygon(contact.a, contact.b, outline, 0.0).empty()) {
            next.push_back(piece);
            continue;
          }
          for (std::vector<uint32_t>& part : cutters[s]->cut(piece, contact.a, contact.b, k))
            next.push_back(std::move(part));
        }
        pieces = std::move(next);
      }
    for (std::vector<uint32_t>& piece : pieces) {
      Element part = element;
      part.corners = std::move(piece);
      cut.push_back(std::move(part));
    }
  }

  // Hidden elements left out, then the nodes no element uses.
  const RayCaster rays(scene);
  std::vector<Element> kept;
  for (Element& element : cut) {
    std::vector<Vec3> outline;
    for (uint32_t node : element.corners) outline.push_back(mesh.nodes[node].position);
    const Vec3 n = element.surface >= 0 && size_t(element.surface) < scene.polygons.size()
                       ? unitNormal(scene.polygons[element.surface].vertices)
                       : unitNormal(outline);
    const std::optional<RayHit> hit = rays.closestHit({centroid(outline), n, n});
    if (!(hit && !hit->front)) kept.push_back(std::move(element));
  }
  std::vector<uint32_t> newIndex(mesh.nodes.size(), UINT32_MAX);
  RadiosityMesh result;
  result.materials = std::move(mesh.materials);
  for (Element& element : kept) {
    for (uint32_t& node : element.corners) {
      if (newIndex[node] == UINT32_MAX) {
        newIndex[node] = uint32_t(result.nodes.size());
        result.nodes.push_back(mesh.nodes[node]);
      }
      node = newIndex[node];
    }
    result.elements.push_back(std::move(element));
  }
  return result;
}

}  // namespace radview
