#pragma once
// Retagging the continuity of element edges in a solution, as Salesin, Lischinski and DeRose
// (1992) do interactively: an edge is C1 (smooth), C0 (B continuous, its derivative not) or
// C-1 (B jumps). A C-1 edge whose two sides share nodes splits them wherever the C-1 edges now
// separate the elements around a node (the solver's discontinuity mesher duplicates nodes the
// same way), and taking the tag away merges them back. Elements keep their indices, so an
// EdgeRef names the same edge before and after any edit.
#include "mesh/radiosity_mesh.h"
#include "mesh/topology.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace radview {

// Edge `edge` of element `element`: corners[edge] -> corners[edge + 1].
struct EdgeRef {
  uint32_t element = 0;
  uint32_t edge = 0;
  bool operator==(const EdgeRef& o) const { return element == o.element && edge == o.edge; }
};

// An edge as the interpolants see it.
struct EdgeDescription {
  EdgeRef ref;
  uint32_t a = 0, b = 0;                   // its end nodes on ref's side
  std::vector<EdgeRef> sides;              // every element side of it, ref's among them; 1 on a boundary
  Continuity continuity = Continuity::C1;  // its tag, or C-1 where its sides have their own nodes
  bool ownNodes = false;                   // the sides do not share their end nodes
};

EdgeDescription describeEdge(const RadiosityMesh& mesh, const MeshTopology& topology, EdgeRef ref);

// C1 -> C0 -> C-1 -> C1: what a click on an edge does.
Continuity nextContinuity(Continuity c);

// Tags the edge `order` (C1 takes the tag away) and splits or merges the nodes at its ends (and
// its mid-edge nodes) to match. Throws Error, leaving the mesh as it was, for an edge out of
// range, or when the edge stops being C-1 but its sides carry different radiosities at a node
// (joining them would change the solution: the tag stays).
void setEdgeContinuity(RadiosityMesh& mesh, EdgeRef ref, Continuity order);
// The same on the mesh's topology (MeshTopology(mesh)), which stays the mesh's: updated in place
// where only the tag changed (edits keep positions, so edges keep their indices), built again
// where nodes were split or joined. A whole topology takes a second or more at 10^6 elements.
void setEdgeContinuity(RadiosityMesh& mesh, MeshTopology& topology, EdgeRef ref, Continuity order);

// Retagging with undo. Each change is one step (a drag across several edges is one change);
// undo sets every edge of the last change back to the continuity it had. The editor keeps the
// edited mesh's topology from one edit to the next, and shares it (a renderer draws with it): the
// mesh must change only through the editor until clear(). A topology still shared when the next
// edit comes is copied first, not changed under its readers.
class ContinuityEditor {
 public:
  // Advances each edge's continuity one step (nextContinuity). Edges that cannot change (see
  // setEdgeContinuity) are left; the first reason is returned, the rest are retagged.
  std::optional<std::string> cycle(RadiosityMesh& mesh, const std::vector<EdgeRef>& edges);
  // Undoes the last change; false when there is none.
  bool undo(RadiosityMesh& mesh);
  size_t steps() const { return history_.size(); }
  // Forgets the history and the topology: for a mesh changed otherwise, or another mesh.
  void clear() {
    history_.clear();
    topology_.reset();
    shared_.reset();
  }
  // The edited mesh's topology (MeshTopology(mesh)), built at the first call after clear().
  std::shared_ptr<const MeshTopology> topology(const RadiosityMesh& mesh);
  // Starts from `topology`, the mesh's (MeshTopology(mesh)) that its renderer has, instead of
  // building one at the first edit; copied when first changed. Ignored once the editor has one.
  void startFrom(const std::shared_ptr<const MeshTopology>& topology) {
    if (!topology_ && !shared_) shared_ = topology;
  }

 private:
  struct Retag {
    EdgeRef edge;
    Continuity before;
  };
  // The topology to change: the editor's own, copied first if it is shared.
  MeshTopology& topologyToEdit(const RadiosityMesh& mesh);
  std::vector<std::vector<Retag>> history_;
  std::shared_ptr<MeshTopology> topology_;
  std::shared_ptr<const MeshTopology> shared_;  // startFrom's, until the first edit copies it
};

}  // namespace radview
