#include "edit/continuity_edit.h"

#include "core/disjoint_sets.h"
#include "core/error.h"
#include "mesh/topology.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <string>

namespace radview {

namespace {

uint32_t cornerAfter(const Element& e, uint32_t i) { return e.corners[(i + 1) % e.corners.size()]; }

std::string name(EdgeRef ref) {
  return "edge " + std::to_string(ref.edge) + " of element " + std::to_string(ref.element);
}

void checkRef(const RadiosityMesh& mesh, EdgeRef ref) {
  if (ref.element >= mesh.elements.size() || ref.edge >= mesh.elements[ref.element].corners.size())
    throw Error(name(ref) + ": no such edge");
}

// The index in topology.edges() of the edge between two positions, if there is one.
std::optional<uint32_t> findEdge(const MeshTopology& topology, uint32_t p, uint32_t q) {
  const auto key = std::minmax(p, q);
  const std::vector<MeshEdge>& edges = topology.edges();
  auto it = std::lower_bound(edges.begin(), edges.end(), key, [](const MeshEdge& e, const auto& k) {
    return std::make_pair(e.a, e.b) < std::make_pair(k.first, k.second);
  });
  if (it == edges.end() || it->a != key.first || it->b != key.second) return std::nullopt;
  return uint32_t(it - edges.begin());
}

bool sameValues(const Node& x, const Node& y, bool gradients) {
  return x.B == y.B && (!gradients || x.gradient == y.gradient);
}

// After the edge between `here` and `there` became C-1: the corners that use `node` are joined
// across every edge at it, not tagged C-1, along which their elements meet: edges leaving the
// node in the same direction, so that an element's long edge meets its neighbours' short ones
// through a T-vertex as the interpolants' triangulation has them meet. If that leaves
// `there`'s corner apart from `here`'s, its part gets a copy of the node. Only a part the
// edited edge alone held together is split off: corners already apart stay as they are.
void splitWhereSeparated(RadiosityMesh& mesh, uint32_t node, EdgeRef here, EdgeRef there,
                         const std::vector<std::vector<bool>>& cm1Tagged) {
  struct Corner {
    uint32_t element, index;
  };
  std::vector<Corner> corners;
  std::map<std::pair<uint32_t, uint32_t>, size_t> cornerIndex;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (uint32_t i = 0; i < mesh.elements[e].corners.size(); ++i)
      if (mesh.elements[e].corners[i] == node) {
        cornerIndex[{e, i}] = corners.size();
        corners.push_back({e, i});
      }
  // A corner's two edges at the node: (edge index, unit direction away from the node).
  const Vec3 at = mesh.nodes[node].position;
  auto edgesAt = [&](const Corner& c) {
    const Element& element = mesh.elements[c.element];
    const uint32_t n = uint32_t(element.corners.size()), previous = (c.index + n - 1) % n;
    auto away = [&](uint32_t other) {
      const Vec3 d = mesh.nodes[other].position - at;
      const double length = glm::length(d);
      return length > 0.0 ? d / length : Vec3(0.0);
    };
    return std::array<std::pair<uint32_t, Vec3>, 2>{
        {{c.index, away(element.corners[(c.index + 1) % n])}, {previous, away(element.corners[previous])}}};
  };
  auto tagged = [&](uint32_t element, uint32_t edge) {
    return edge < cm1Tagged[element].size() && cm1Tagged[element][edge];
  };
  auto isEdited = [&](uint32_t element, uint32_t edge) {
    return (element == here.element && edge == here.edge) || (element == there.element && edge == there.edge);
  };
  // Joins the corners whose elements meet along an untagged edge at the node, the edited one
  // counted only when `withEdited`.
  auto parts = [&](bool withEdited) {
    DisjointSets sets(corners.size());
    for (size_t i = 0; i < corners.size(); ++i)
      for (size_t j = i + 1; j < corners.size(); ++j)
        for (const auto& [ei, di] : edgesAt(corners[i]))
          for (const auto& [ej, dj] : edgesAt(corners[j])) {
            if (glm::dot(di, dj) < 1.0 - 1e-9) continue;
            const uint32_t a = corners[i].element, b = corners[j].element;
            const bool edited = isEdited(a, ei) || isEdited(b, ej);
            if (edited ? !withEdited : tagged(a, ei) || tagged(b, ej)) continue;
            sets.join(i, j);
          }
    return sets;
  };
  DisjointSets with = parts(true), without = parts(false);
  const Element& e = mesh.elements[here.element];
  const uint32_t hereIndex = e.corners[here.edge] == node ? here.edge : (here.edge + 1) % uint32_t(e.corners.size());
  const Element& f = mesh.elements[there.element];
  const uint32_t thereIndex =
      f.corners[there.edge] == node ? there.edge : (there.edge + 1) % uint32_t(f.corners.size());
  const size_t h = cornerIndex.at({here.element, hereIndex}), t = cornerIndex.at({there.element, thereIndex});
  if (with.find(h) != with.find(t) || without.find(h) == without.find(t)) return;
  const uint32_t copy = uint32_t(mesh.nodes.size());
  mesh.nodes.push_back(mesh.nodes[node]);
  for (size_t c = 0; c < corners.size(); ++c)
    if (without.find(c) == without.find(t)) mesh.elements[corners[c].element].corners[corners[c].index] = copy;
}

// Every use of `replaced` becomes `kept`; `replaced` goes, and the nodes after it move down.
void joinNodes(RadiosityMesh& mesh, uint32_t kept, uint32_t replaced) {
  for (Element& e : mesh.elements)
    for (auto* list : {&e.corners, &e.midEdge})
      for (uint32_t& n : *list) n = n == replaced ? kept : n > replaced ? n - 1 : n;
  mesh.nodes.erase(mesh.nodes.begin() + replaced);
}

}  // namespace

Continuity nextContinuity(Continuity c) {
  switch (c) {
    case Continuity::C1:
      return Continuity::C0;
    case Continuity::C0:
      return Continuity::Cm1;
    case Continuity::Cm1:
      return Continuity::C1;
  }
  return Continuity::C1;
}

EdgeDescription describeEdge(const RadiosityMesh& mesh, const MeshTopology& topology, EdgeRef ref) {
  checkRef(mesh, ref);
  EdgeDescription d;
  d.ref = ref;
  const Element& element = mesh.elements[ref.element];
  d.a = element.corners[ref.edge];
  d.b = cornerAfter(element, ref.edge);
  const MeshEdge& edge = topology.edges()[topology.edgeIndex(ref.element, ref.edge)];
  for (const EdgeSide& side : topology.sides(edge)) {
    d.sides.push_back({side.element, side.edge});
    const Element& other = mesh.elements[side.element];
    const uint32_t a = other.corners[side.edge], b = cornerAfter(other, side.edge);
    if (!((a == d.a && b == d.b) || (a == d.b && b == d.a))) d.ownNodes = true;
  }
  d.continuity = d.ownNodes ? Continuity::Cm1 : edge.continuity;
  return d;
}

void setEdgeContinuity(RadiosityMesh& mesh, EdgeRef ref, Continuity order) {
  checkRef(mesh, ref);
  MeshTopology topology(mesh);
  setEdgeContinuity(mesh, topology, ref, order);
}

void setEdgeContinuity(RadiosityMesh& mesh, MeshTopology& topology, EdgeRef ref, Continuity order) {
  checkRef(mesh, ref);
  const size_t nodesBefore = mesh.nodes.size();
  const uint32_t edited = topology.edgeIndex(ref.element, ref.edge);
  const EdgeDescription was = describeEdge(mesh, topology, ref);

  // Every tag as the edge it is on (elements keep their indices through the edit, nodes not),
  // the edited edge's replaced by the new one.
  std::vector<std::pair<EdgeRef, Continuity>> tags;
  for (const DiscontinuityEdge& tag : mesh.discontinuities) {
    const std::optional<uint32_t> e = findEdge(topology, topology.positionId(tag.a), topology.positionId(tag.b));
    RADVIEW_CHECK(e.has_value());  // the topology refuses tags that are not element edges
    if (*e == edited) continue;
    const EdgeSide& side = topology.sides(topology.edges()[*e])[0];
    tags.push_back({{side.element, side.edge}, tag.order});
  }
  if (order != Continuity::C1) tags.push_back({ref, order});

  // Only an edge between two elements has sides to split or join.
  if (was.sides.size() == 2) {
    const EdgeRef other = was.sides[0] == ref ? was.sides[1] : was.sides[0];
    const std::array<uint32_t, 2> otherEnds = {mesh.elements[other.element].corners[other.edge],
                                               cornerAfter(mesh.elements[other.element], other.edge)};
    // The other side's node at the same position as `node` of this side.
    auto across = [&](uint32_t node) {
      const uint32_t p = topology.positionId(node);
      return topology.positionId(otherEnds[0]) == p ? otherEnds[0] : otherEnds[1];
    };
    const Element& here = mesh.elements[ref.element];
    const Element& there = mesh.elements[other.element];
    const bool quadratic = !here.midEdge.empty() && !there.midEdge.empty();
    if (order == Continuity::Cm1 && !was.ownNodes) {
      std::vector<std::vector<bool>> cm1Tagged(mesh.elements.size());
      for (const auto& [side, o] : tags)
        if (o == Continuity::Cm1) {
          for (const EdgeSide& s : topology.sides(topology.edges()[topology.edgeIndex(side.element, side.edge)])) {
            cm1Tagged[s.element].resize(mesh.elements[s.element].corners.size(), false);
            cm1Tagged[s.element][s.edge] = true;
          }
        }
      for (uint32_t node : {was.a, was.b}) splitWhereSeparated(mesh, node, ref, other, cm1Tagged);
      if (quadratic && here.midEdge[ref.edge] == there.midEdge[other.edge]) {
        mesh.elements[other.element].midEdge[other.edge] = uint32_t(mesh.nodes.size());
        mesh.nodes.push_back(mesh.nodes[here.midEdge[ref.edge]]);
      }
    } else if (order != Continuity::Cm1 && was.ownNodes) {
      std::vector<std::pair<uint32_t, uint32_t>> joins;  // (kept, replaced)
      for (uint32_t node : {was.a, was.b})
        if (across(node) != node) joins.push_back(std::minmax(node, across(node)));
      if (quadratic && here.midEdge[ref.edge] != there.midEdge[other.edge])
        joins.push_back(std::minmax(here.midEdge[ref.edge], there.midEdge[other.edge]));
      for (const auto& [kept, replaced] : joins)
        if (!sameValues(mesh.nodes[kept], mesh.nodes[replaced], mesh.hasGradients))
          throw Error(name(ref) + ": its sides carry different radiosities at nodes " + std::to_string(kept) + " and " +
                      std::to_string(replaced) + "; joining them would change the solution, so it stays C-1");
      // Highest first, so that removing one does not move those still to go.
      std::sort(joins.begin(), joins.end(), [](const auto& x, const auto& y) { return x.second > y.second; });
      joins.erase(std::unique(joins.begin(), joins.end()), joins.end());
      for (const auto& [kept, replaced] : joins) joinNodes(mesh, kept, replaced);
    }
  }

  // The tags again, on the nodes their edges now have.
  mesh.discontinuities.clear();
  for (const auto& [side, o] : tags) {
    const Element& e = mesh.elements[side.element];
    mesh.discontinuities.push_back({e.corners[side.edge], cornerAfter(e, side.edge), o});
  }
  // Splits only add nodes and joins only remove them: the same count, the same nodes. Every
  // other tag is as it was, one tag per edited edge, so the edge's continuity is `order`.
  if (mesh.nodes.size() == nodesBefore)
    topology.setContinuity(edited, order);
  else
    topology = MeshTopology(mesh);
}

std::shared_ptr<const MeshTopology> ContinuityEditor::topology(const RadiosityMesh& mesh) {
  if (topology_) return topology_;
  if (!shared_) shared_ = std::make_shared<const MeshTopology>(mesh);
  return shared_;
}

MeshTopology& ContinuityEditor::topologyToEdit(const RadiosityMesh& mesh) {
  if (!topology_) {
    // A copy of the one it started from (about a tenth of the time of building one).
    topology_ = shared_ ? std::make_shared<MeshTopology>(*shared_) : std::make_shared<MeshTopology>(mesh);
    shared_.reset();
  } else if (topology_.use_count() > 1) {  // only this thread hands it out: no new reader can appear meanwhile
    topology_ = std::make_shared<MeshTopology>(*topology_);
  }
  return *topology_;
}

std::optional<std::string> ContinuityEditor::cycle(RadiosityMesh& mesh, const std::vector<EdgeRef>& edges) {
  std::optional<std::string> refused;
  std::vector<Retag> change;
  // An edge picked from both of its sides is one edge. Edits keep positions, so edge indices
  // name the same edges throughout.
  MeshTopology& topology = topologyToEdit(mesh);
  std::vector<uint32_t> done;
  for (const EdgeRef& ref : edges) {
    checkRef(mesh, ref);
    const uint32_t index = topology.edgeIndex(ref.element, ref.edge);
    if (std::find(done.begin(), done.end(), index) != done.end()) continue;
    done.push_back(index);
    const Continuity now = describeEdge(mesh, topology, ref).continuity;
    try {
      setEdgeContinuity(mesh, topology, ref, nextContinuity(now));
      change.push_back({ref, now});
    } catch (const Error& e) {
      if (!refused) refused = e.what();
    }
  }
  if (!change.empty()) history_.push_back(std::move(change));
  return refused;
}

bool ContinuityEditor::undo(RadiosityMesh& mesh) {
  if (history_.empty()) return false;
  const std::vector<Retag> change = std::move(history_.back());
  history_.pop_back();
  MeshTopology& topology = topologyToEdit(mesh);
  for (auto it = change.rbegin(); it != change.rend(); ++it) setEdgeContinuity(mesh, topology, it->edge, it->before);
  return true;
}

}  // namespace radview
