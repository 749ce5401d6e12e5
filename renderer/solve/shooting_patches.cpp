#include "solve/shooting_patches.h"

#include "core/error.h"
#include "geom/polygon.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

namespace radview {

namespace {

// A grid over one polygon, in its plane: `cells` x `cells` cells spanning its 2D bounds.
struct SurfaceGrid {
  PlaneFrame frame;
  Vec2 lo{0.0}, cellSize{1.0};
  int64_t columns = 1, rows = 1;

  SurfaceGrid(const std::vector<Vec3>& polygon, double size) : frame(planeFrame(polygon)) {
    Vec2 hi(-INFINITY);
    lo = Vec2(INFINITY);
    for (const Vec3& v : polygon) {
      lo = glm::min(lo, frame.project(v));
      hi = glm::max(hi, frame.project(v));
    }
    columns = std::max<int64_t>(1, std::llround((hi.x - lo.x) / size));
    rows = std::max<int64_t>(1, std::llround((hi.y - lo.y) / size));
    cellSize = (hi - lo) / Vec2(double(columns), double(rows));
  }
  std::pair<int64_t, int64_t> cellOf(const Vec3& p) const {
    const Vec2 c = (frame.project(p) - lo) / cellSize;
    return {std::clamp<int64_t>(int64_t(std::floor(c.x)), 0, columns - 1),
            std::clamp<int64_t>(int64_t(std::floor(c.y)), 0, rows - 1)};
  }
};

}  // namespace

std::vector<uint32_t> groupIntoShootingPatches(const Scene& scene, const RadiosityMesh& mesh, double size) {
  if (!(size > 0.0 && std::isfinite(size))) throw Error("shooting patch size must be positive and finite");
  std::vector<std::optional<SurfaceGrid>> grids(scene.polygons.size());
  for (size_t s = 0; s < scene.polygons.size(); ++s)
    if (area(scene.polygons[s].vertices) > 0.0) grids[s].emplace(scene.polygons[s].vertices, size);
  std::map<std::tuple<int, int, int64_t, int64_t>, uint32_t> patchOfCell;
  std::vector<uint32_t> patchOf(mesh.elements.size());
  uint32_t patches = 0;
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& element = mesh.elements[e];
    if (element.surface < 0 || size_t(element.surface) >= grids.size() || !grids[element.surface]) {
      patchOf[e] = patches++;
      continue;
    }
    const auto [column, row] = grids[element.surface]->cellOf(centroid(mesh.cornerPositions(e)));
    const auto [cell, added] =
        patchOfCell.emplace(std::make_tuple(element.surface, element.material, column, row), patches);
    if (added) ++patches;
    patchOf[e] = cell->second;
  }
  return patchOf;
}

}  // namespace radview
