#include "interp/point_sampling.h"

#include "core/error.h"
#include "core/parallel_for.h"
#include "interp/surface_locator.h"
#include "interp/thin_plate.h"

#include <optional>

namespace radview {

InterpolantOptions interpolantOptionsFromNames(const std::string& diagonal, const std::string& variant,
                                               const std::string& smoothing, bool estimateGradients) {
  InterpolantOptions options;
  if (diagonal != "02" && diagonal != "13") throw Error("--diagonal '" + diagonal + "': expected 02 or 13");
  options.diagonal = diagonal == "13" ? QuadDiagonal::D13 : QuadDiagonal::D02;
  options.cloughTocher = cloughTocherVariantFromName(variant);
  options.thinPlate = thinPlateSettingsFromText(smoothing);
  options.useStoredGradients = !estimateGradients;
  return options;
}

void forEachPlacedPoint(const RadiosityMesh& mesh, size_t count, const std::function<PointQuery(size_t)>& query,
                        double maxDistance, const std::function<void(size_t, const SurfacePoint&)>& use,
                        const SurfaceLocator* locator) {
  bool anyWorldPoint = false;
  for (size_t i = 0; i < count && !anyWorldPoint; ++i) anyWorldPoint = query(i).element == PointQuery::kWorldPoint;
  std::optional<SurfaceLocator> built;
  if (anyWorldPoint && !locator) locator = &built.emplace(mesh);
  parallelFor(count, [&](size_t i) {
    const PointQuery q = query(i);
    SurfacePoint point;
    if (q.element == PointQuery::kWorldPoint) {
      point = locator->nearest(q.values, maxDistance);
    } else {
      point.element = q.element;
      point.x = pointFromBarycentric(mesh, q.element, q.values);
    }
    use(i, point);
  });
}

std::vector<SurfacePoint> placePoints(const RadiosityMesh& mesh, size_t count,
                                      const std::function<PointQuery(size_t)>& query, double maxDistance) {
  std::vector<SurfacePoint> points(count);
  forEachPlacedPoint(mesh, count, query, maxDistance, [&](size_t i, const SurfacePoint& p) { points[i] = p; });
  return points;
}

std::vector<uint32_t> orderByElement(const uint32_t* element, size_t count, size_t elementCount) {
  std::vector<uint32_t> start(elementCount + 1, 0);
  for (size_t i = 0; i < count; ++i) ++start[element[i] + 1];
  for (size_t e = 0; e < elementCount; ++e) start[e + 1] += start[e];
  std::vector<uint32_t> order(count);
  for (size_t i = 0; i < count; ++i) order[start[element[i]]++] = uint32_t(i);
  return order;
}

size_t firstOffSurface(const std::vector<SurfacePoint>& points, double maxDistance) {
  for (size_t i = 0; i < points.size(); ++i)
    if (points[i].distance > maxDistance) return i;
  return points.size();
}

StandardErrorField::StandardErrorField(const RadiosityMesh& mesh, const InterpolantOptions& options) : errors_(mesh) {
  for (Node& node : errors_.nodes) node.B = node.standardError;
  interpolant_ = makeInterpolant(errors_, Method::Gouraud, options);
}

}  // namespace radview
