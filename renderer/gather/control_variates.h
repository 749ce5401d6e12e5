#pragma once
// Control variates for the final gather's integral (C&W eq. 9.9): a function h close to the
// integrand f whose integral is known in closed form. The gather adds h's integral exactly and
// samples only f - h:
//   integral of f = integral of h + E[(f - h) / pdf],
// unbiased for any h, with the variance of f - h in place of f's.
//
// h stands the scene in by its planes: the mesh's elements grouped into planes, each plane
// replaced by its convex hull with one radiosity, the area mean of B^ - E over it (emitters:
// also their E). From a point x the hulls hide one another as the surfaces do
// (occluding_polygons.h), so h is, in every direction, the radiosity of the hull met first, and
// its integral is the sum over the hulls of that radiosity times the form factor to what x sees
// of the hull (Lambert's formula over the visible pieces). What is left to sample is B^'s
// variation within a plane and where the hulls differ from the surfaces; in the Cornell box
// the blocks hide the walls as their hulls do, and their shadows are in h. Only hulls that
// face x hide: at a point the surfaces enclose (the floor under a block), which sees their
// backs alone, h is no help, though the estimate stays unbiased.
#include "gather/emitter_sampler.h"
#include "gather/occluding_polygons.h"
#include "mesh/radiosity_mesh.h"
#include "trace/form_factor.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace radview {

class SceneControl {
 public:
  // What h is on one hull: B^ - E, constant on each cell of a grid over the hull (the cells
  // follow B^ across a large plane; an emitter's hull is one cell), and E where the hull is a
  // convex emitter.
  struct HullRadiosity {
    Vec3 origin, t, b;  // the grid's frame in the hull's plane
    Vec2 low, cellSize;
    int columns = 1, rows = 1;
    std::vector<Rgb> reflected;  // per cell, row-major
    Rgb emitted{0.0};
    size_t cellOf(const Vec3& p) const;
  };
  explicit SceneControl(const RadiosityMesh& mesh);

  // The hulls x is in front of (OccludingPolygons::facing): formed once per point.
  uint64_t facing(const Vec3& x) const { return hulls_.facing(x); }
  // Both controls' integrals at x (unit normal n): the direct part (the emitters' E) and the
  // indirect part (the hulls' B^ - E).
  Rgb integral(const Vec3& x, const Vec3& n, uint64_t facing) const;
  // The indirect control in one direction from x: the radiosity (B^ - E) of the hull seen.
  Rgb along(const Vec3& x, const Vec3& direction, uint64_t facing) const;
  // The direct control's visibility of an emitter point from x: 1 where the hull of its emitter
  // is seen, for an emitter whose hull is the emitter itself (a convex one); 1 everywhere for
  // the others, whose control is their light with nothing in the way.
  bool emitterSeen(const Vec3& x, const EmitterSample& sample, uint64_t facing) const;

  size_t hullCount() const { return hulls_.size(); }

 private:
  // h's integral over one visible piece of a hull: the piece cut along the grid's lines.
  Rgb pieceIntegral(const HullRadiosity& hull, const Vec3& x, const Vec3& n, const std::vector<Vec3>& piece) const;
  OccludingPolygons hulls_;
  std::vector<HullRadiosity> radiosities_;                // per hull
  std::unordered_map<uint32_t, uint32_t> hullOfEmitter_;  // emitter element -> its hull, if convex
  // The other emitters, with no occlusion: Lambert's sum over each group's outline.
  struct UnoccludedEmitter {
    PatchFormFactor formFactor;
    Rgb E;
  };
  std::vector<UnoccludedEmitter> unoccluded_;
};

}  // namespace radview
