#include "solve/element_to_node.h"

namespace radview {

namespace {

// The estimator both functions share; `sampleB(k)` is what sample k carries, `meanB` what the
// whole patch shoots on average (the answer when no sample is in front of both).
template <typename Value, typename SampleValue>
Value gather(const ReceiverPoint& x, const PatchSampler& shooter, const SampleValue& sampleB, const Value& meanB,
             SampleStream& stream, const RayCaster* visibility, size_t& rays, std::vector<AreaSample>& scratch) {
  double F0 = shooter.unoccluded().from(x.position, x.normal);
  if (F0 == 0.0 && x.inside) F0 = shooter.unoccluded().from(*x.inside, x.normal);
  if (F0 == 0.0) return Value(0.0);
  const Vec3 origin = x.inside.value_or(x.position);
  if (!visibility) return F0 * meanB;
  if (scratch.size() < shooter.samples()) scratch.resize(shooter.samples());
  shooter.draw(stream, scratch.data());
  const AreaSample* const samples = scratch.data();
  const Vec3& N = shooter.normal();
  // The samples in front of both, with their kernel, and their rays cast together.
  thread_local std::vector<const AreaSample*> facing;
  thread_local std::vector<double> kernel;
  thread_local std::vector<Vec3> targets;
  thread_local std::vector<uint8_t> blocked;
  facing.clear(), kernel.clear(), targets.clear();
  double all = 0.0;
  for (size_t k = 0; k < shooter.samples(); ++k) {
    const AreaSample& sample = samples[k];
    const Vec3 d = sample.position - origin;
    const double r2 = glm::dot(d, d);
    const double K = sample.weight * std::max(0.0, glm::dot(x.normal, d)) * std::max(0.0, -glm::dot(N, d)) / (r2 * r2);
    if (!(K > 0.0)) continue;
    all += K;
    facing.push_back(&sample);
    kernel.push_back(K);
    targets.push_back(sample.position);
  }
  rays += targets.size();
  blocked.resize(targets.size());
  visibility->occludedFrom(origin, x.normal, targets.data(), targets.size(), N, blocked.data());
  Value seen(0.0);
  for (size_t i = 0; i < facing.size(); ++i)
    if (!blocked[i]) seen += kernel[i] * sampleB(*facing[i]);
  // No sample in front of both (a sliver of the shooter above the horizon that the samples
  // missed): nothing says it is hidden.
  return all > 0.0 ? F0 * (seen / all) : F0 * meanB;
}

}  // namespace

double elementToNodeFormFactor(const ReceiverPoint& x, const PatchSampler& shooter, SampleStream& stream,
                               const RayCaster* visibility, size_t& rays, std::vector<AreaSample>& scratch) {
  return gather(
      x, shooter, [](const AreaSample&) { return 1.0; }, 1.0, stream, visibility, rays, scratch);
}

Rgb radiosityFromPatch(const ReceiverPoint& x, const PatchSampler& shooter, const std::vector<Rgb>& polygonB,
                       SampleStream& stream, const RayCaster* visibility, size_t& rays,
                       std::vector<AreaSample>& scratch) {
  if (polygonB.size() == 1)  // one radiosity: the form factor times it, the same bits as alone
    return polygonB[0] * elementToNodeFormFactor(x, shooter, stream, visibility, rays, scratch);
  Rgb mean(0.0);
  for (size_t p = 0; p < polygonB.size(); ++p) mean += polygonB[p] * shooter.polygonArea(p);
  mean /= shooter.area();
  return gather(
      x, shooter, [&](const AreaSample& s) { return polygonB[s.polygon]; }, mean, stream, visibility, rays, scratch);
}

}  // namespace radview
