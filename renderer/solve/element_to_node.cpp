#include "solve/element_to_node.h"

#include "solve/form_factor.h"

namespace radview {

double elementToNodeFormFactor(const ReceiverPoint& x, const PatchSampler& shooter, SampleStream& stream,
                               const RayCaster* visibility, size_t& rays, std::vector<AreaSample>& scratch) {
  const double F0 = pointToPolygonFormFactor(x.position, x.normal, shooter.corners());
  if (F0 == 0.0 || !visibility) return F0;
  scratch.clear();
  shooter.draw(stream, scratch);
  const Vec3& N = shooter.normal();
  double seen = 0.0, all = 0.0;
  for (const AreaSample& sample : scratch) {
    const Vec3 d = sample.position - x.position;
    const double r2 = glm::dot(d, d);
    const double K = sample.weight * std::max(0.0, glm::dot(x.normal, d)) * std::max(0.0, -glm::dot(N, d)) / (r2 * r2);
    if (!(K > 0.0)) continue;
    all += K;
    ++rays;
    if (!visibility->occluded({x.position, x.normal, sample.position, N})) seen += K;
  }
  // No sample in front of both (a sliver of the shooter above the horizon that the samples
  // missed): nothing says it is hidden.
  return all > 0.0 ? F0 * (seen / all) : F0;
}

}  // namespace radview
