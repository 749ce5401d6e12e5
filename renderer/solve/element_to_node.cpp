#include "solve/element_to_node.h"

#include <algorithm>
#include <cmath>

namespace radview {

namespace {

double root(double v) { return std::sqrt(v); }
Rgb root(const Rgb& v) { return glm::sqrt(v); }

// One batch of the shooter's samples from x: the kernel over the samples in front of both, the
// part of it whose rays are clear, and that part weighted by what each sample carries.
template <typename Value>
struct Batch {
  double all = 0.0, clear = 0.0;
  Value seen{0.0};
  size_t facing = 0, visible = 0;
  // The variance of seen / all from the batch's own samples, as if they were independent (a
  // stratified set spreads less, so this errs high): sum_k K_k^2 (v_k - m)^2 / (sum_k K_k)^2,
  // v_k what sample k brings (0 when blocked), m = seen / all; the delta method for a ratio.
  Value variance{0.0};
};

template <typename Value, typename SampleValue>
Batch<Value> castBatch(const Vec3& origin, const ReceiverPoint& x, const PatchSampler& shooter,
                       const SampleValue& sampleB, SampleStream& stream, const RayCaster& visibility, size_t& rays,
                       std::vector<AreaSample>& scratch) {
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
  Batch<Value> batch;
  for (size_t k = 0; k < shooter.samples(); ++k) {
    const AreaSample& sample = samples[k];
    const Vec3 d = sample.position - origin;
    const double r2 = glm::dot(d, d);
    const double K = sample.weight * std::max(0.0, glm::dot(x.normal, d)) * std::max(0.0, -glm::dot(N, d)) / (r2 * r2);
    if (!(K > 0.0)) continue;
    batch.all += K;
    facing.push_back(&sample);
    kernel.push_back(K);
    targets.push_back(sample.position);
  }
  rays += targets.size();
  blocked.resize(targets.size());
  visibility.occludedFrom(origin, x.normal, targets.data(), targets.size(), N, blocked.data());
  batch.facing = facing.size();
  for (size_t i = 0; i < facing.size(); ++i)
    if (!blocked[i]) {
      batch.clear += kernel[i];
      batch.seen += kernel[i] * sampleB(*facing[i]);
      ++batch.visible;
    }
  if (batch.all > 0.0) {
    const Value mean = batch.seen / batch.all;
    for (size_t i = 0; i < facing.size(); ++i) {
      const Value d = (blocked[i] ? Value(0.0) : Value(sampleB(*facing[i]))) - mean;
      batch.variance += kernel[i] * kernel[i] * d * d;
    }
    batch.variance /= batch.all * batch.all;
  }
  return batch;
}

// The estimator both functions share; `sampleB(k)` is what sample k carries, `meanB` what the
// whole patch shoots on average (the answer when no sample is in front of both).
template <typename Value, typename SampleValue>
Value gather(const ReceiverPoint& x, const PatchSampler& shooter, const SampleValue& sampleB, const Value& meanB,
             SampleStream& stream, const RayCaster* visibility, size_t& rays, std::vector<AreaSample>& scratch,
             const VisibilitySampling& sampling, Value* standardError) {
  if (standardError) *standardError = Value(0.0);
  double F0 = shooter.unoccluded().from(x.position, x.normal);
  if (F0 == 0.0 && x.inside) F0 = shooter.unoccluded().from(*x.inside, x.normal);
  if (F0 == 0.0) return Value(0.0);
  const Vec3 origin = x.inside.value_or(x.position);
  if (!visibility) return F0 * meanB;
  Batch<Value> total = castBatch<Value>(origin, x, shooter, sampleB, stream, *visibility, rays, scratch);
  // No sample in front of both (a sliver of the shooter above the horizon that the samples
  // missed): nothing says it is hidden.
  if (!(total.all > 0.0)) return F0 * meanB;
  const bool settled = total.visible == 0 || total.visible == total.facing;
  if (settled || sampling.maxBatches <= 1) {
    if (standardError) *standardError = F0 * root(total.variance);
    return F0 * (total.seen / total.all);
  }
  // Seen in part: batches until the visible fraction's standard error meets the target.
  std::vector<double> fractions{total.clear / total.all};
  std::vector<Value> estimates{F0 * (total.seen / total.all)};
  auto fractionError = [&] {
    const double n = double(fractions.size());
    double mean = 0.0, squares = 0.0;
    for (double f : fractions) mean += f / n;
    for (double f : fractions) squares += (f - mean) * (f - mean);
    return std::sqrt(squares / (n * (n - 1.0)));
  };
  while (int(fractions.size()) < sampling.maxBatches &&
         (int(fractions.size()) < std::max(2, sampling.minBatches) || fractionError() > sampling.targetError)) {
    const Batch<Value> batch = castBatch<Value>(origin, x, shooter, sampleB, stream, *visibility, rays, scratch);
    if (!(batch.all > 0.0)) break;
    total.all += batch.all;
    total.seen += batch.seen;
    fractions.push_back(batch.clear / batch.all);
    estimates.push_back(F0 * (batch.seen / batch.all));
  }
  if (standardError && estimates.size() > 1) {
    const double n = double(estimates.size());
    Value mean(0.0), squares(0.0);
    for (const Value& e : estimates) mean += e / n;
    for (const Value& e : estimates) squares += (e - mean) * (e - mean);
    *standardError = root(squares / (n * (n - 1.0)));
  }
  return F0 * (total.seen / total.all);
}

}  // namespace

double elementToNodeFormFactor(const ReceiverPoint& x, const PatchSampler& shooter, SampleStream& stream,
                               const RayCaster* visibility, size_t& rays, std::vector<AreaSample>& scratch,
                               const VisibilitySampling& sampling, double* standardError) {
  return gather(
      x, shooter, [](const AreaSample&) { return 1.0; }, 1.0, stream, visibility, rays, scratch, sampling,
      standardError);
}

Rgb radiosityFromPatch(const ReceiverPoint& x, const PatchSampler& shooter, const std::vector<Rgb>& polygonB,
                       SampleStream& stream, const RayCaster* visibility, size_t& rays,
                       std::vector<AreaSample>& scratch, const VisibilitySampling& sampling, Rgb* standardError) {
  if (polygonB.size() == 1) {  // one radiosity: the form factor times it, the same bits as alone
    double error = 0.0;
    const double F = elementToNodeFormFactor(x, shooter, stream, visibility, rays, scratch, sampling, &error);
    if (standardError) *standardError = glm::abs(polygonB[0]) * error;
    return polygonB[0] * F;
  }
  Rgb mean(0.0);
  for (size_t p = 0; p < polygonB.size(); ++p) mean += polygonB[p] * shooter.polygonArea(p);
  mean /= shooter.area();
  return gather(
      x, shooter, [&](const AreaSample& s) { return polygonB[s.polygon]; }, mean, stream, visibility, rays, scratch,
      sampling, standardError);
}

}  // namespace radview
