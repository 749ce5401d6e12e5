#pragma once
// The reference interpolants at points a caller names: world points placed on their nearest
// element, or barycentric coordinates on a given one, then evaluated. What `radview sample` and
// the Python module's sample() share; each reads and reports the points its own way.
#include "interp/interpolant.h"
#include "interp/surface_locator.h"
#include "interp/surface_point.h"
#include "mesh/radiosity_mesh.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace radview {

// One point: a world position (element == kWorldPoint), or barycentric coordinates in the
// first three corners of `element`.
struct PointQuery {
  static constexpr uint32_t kWorldPoint = std::numeric_limits<uint32_t>::max();
  uint32_t element = kWorldPoint;
  Vec3 values{0.0};
};

// The interpolant settings named as the command line names them (--diagonal 02|13, --variant,
// --smoothing, --estimate-gradients). Throws Error naming the option.
InterpolantOptions interpolantOptionsFromNames(const std::string& diagonal, const std::string& variant,
                                               const std::string& smoothing, bool estimateGradients);

// Places `count` points on every core: query(i) says where the i-th is. World points go to their
// nearest surface point through a SurfaceLocator (built only when one is asked for), searched
// first within maxDistance; the others to their barycentric point, at distance 0. A world point
// farther than maxDistance from every element keeps its nearest point and distance: the caller
// reports it (firstOffSurface).
std::vector<SurfacePoint> placePoints(const RadiosityMesh& mesh, size_t count,
                                      const std::function<PointQuery(size_t)>& query, double maxDistance);
// The same, handing each point to use(i, point) on the core that placed it, while it is in
// cache, instead of keeping them all. `locator`, where the caller keeps one of `mesh` between
// calls, places the world points instead of one built here.
void forEachPlacedPoint(const RadiosityMesh& mesh, size_t count, const std::function<PointQuery(size_t)>& query,
                        double maxDistance, const std::function<void(size_t, const SurfacePoint&)>& use,
                        const SurfaceLocator* locator = nullptr);
// The indices 0..count-1 ordered by element[i] (a counting sort: stable, O(count + elements)).
// Evaluating in this order reads each element's patch from memory once for all its points
// instead of once per point: a Clough-Tocher patch is 900 bytes, and a million random points
// on 40,000 triangles otherwise miss the cache on nearly every one.
std::vector<uint32_t> orderByElement(const uint32_t* element, size_t count, size_t elementCount);
// The index of the first point farther than maxDistance, or points.size().
size_t firstOffSurface(const std::vector<SurfacePoint>& points, double maxDistance);

// The solver's standard errors of B between the nodes, interpolated linearly (Gouraud) as the
// standard-error view draws them. The mesh must hold them (hasStandardErrors).
class StandardErrorField {
 public:
  StandardErrorField(const RadiosityMesh& mesh, const InterpolantOptions& options);
  Rgb at(const SurfacePoint& point) const { return interpolant_->evaluate(point.element, point.x).B; }

 private:
  RadiosityMesh errors_;  // the mesh with each node's B replaced by its standard error
  std::unique_ptr<Interpolant> interpolant_;
};

}  // namespace radview
