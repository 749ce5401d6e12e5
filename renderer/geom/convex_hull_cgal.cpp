#include "geom/convex_hull_cgal.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Convex_hull_traits_adapter_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/property_map.h>

#include <numeric>

namespace radview {

std::vector<int> convexHull2(const std::vector<Vec2>& points) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_2> cgalPoints;
  cgalPoints.reserve(points.size());
  for (const Vec2& p : points) cgalPoints.emplace_back(p.x, p.y);
  // Hull of the indices, compared through the points they name.
  std::vector<int> indices(points.size());
  std::iota(indices.begin(), indices.end(), 0);
  using Traits = CGAL::Convex_hull_traits_adapter_2<Kernel, CGAL::Pointer_property_map<Kernel::Point_2>::type>;
  std::vector<int> hull;
  CGAL::convex_hull_2(indices.begin(), indices.end(), std::back_inserter(hull),
                      Traits(CGAL::make_property_map(cgalPoints)));
  return hull;
}

}  // namespace radview
