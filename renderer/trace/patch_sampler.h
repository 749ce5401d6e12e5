#pragma once
// Area sampling of a shooting patch for the visibility of the element-to-node form factor
// (Wallace, Elmquist, Haines 1989): a patch (one polygon, or several coplanar ones) is cut into
// pieces (a polygon itself when it is a planar convex quad or a triangle, else its triangles),
// each sampled on a jittered k x k grid of its parameter square, every sample weighted by the
// area it stands for.
#include "core/types.h"
#include "trace/form_factor.h"

#include <cstdint>
#include <vector>

namespace radview {

// A small, fast generator with a 64-bit state (SplitMix64, Steele et al. 2014): one per
// (seed, shot, node), so results do not depend on which thread draws them.
class SampleStream {
 public:
  explicit SampleStream(uint64_t state) : state_(state) {}
  // A well-mixed seed for the stream of `a`, `b`, `c` (e.g. seed, shot, node).
  static SampleStream forKey(uint64_t a, uint64_t b, uint64_t c);
  uint64_t next();
  // What next() returns after i more calls, without stepping: the state is a counter.
  uint64_t at(uint64_t i) const;
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)

 private:
  uint64_t state_;
};

struct AreaSample {
  Vec3 position;
  double weight = 0.0;   // the area this sample stands for; the weights sum to about the area
  uint32_t polygon = 0;  // which of the patch's polygons it lies on
};

class PatchSampler {
 public:
  // `corners`: a planar simple polygon (CCW about its normal). About `samples` samples are
  // drawn (each piece gets at least one, and a square number): samples() says how many.
  // Throws Error for a degenerate polygon.
  PatchSampler(const std::vector<Vec3>& corners, int samples);
  // A patch of several non-overlapping polygons in one plane, facing one way (elements grouped
  // into one shooter, shooting_patches.h); the samples are shared out by area. Its normal is
  // that of the largest polygon. Throws Error when their total area is zero.
  PatchSampler(const std::vector<std::vector<Vec3>>& polygons, int samples);

  // The patch's exact unoccluded form factor from a receiving point (form_factor.h).
  const PatchFormFactor& unoccluded() const { return unoccluded_; }
  double area() const { return area_; }
  double polygonArea(size_t polygon) const { return polygonAreas_[polygon]; }
  const Vec3& normal() const { return normal_; }
  size_t samples() const { return sampleCount_; }
  // Appends samples() jittered samples, one per grid cell of every piece.
  void draw(SampleStream& stream, std::vector<AreaSample>& out) const;
  // The same samples written to out[0 .. samples()), for a caller that keeps a buffer of that
  // size: the solver draws for every node and shot.
  void draw(SampleStream& stream, AreaSample* out) const;

 private:
  struct Piece {
    Vec3 a, b, c, d;  // a triangle (a, b, c), or a bilinear quad (a, b, c, d) when `quad`
    bool quad = false;
    uint32_t polygon = 0;
    int k = 1;            // k x k grid
    double weight = 0.0;  // triangle: area / k^2 (the map below preserves area)
    Vec3 jacobian{0.0};   // quad: |dp/du x dp/dv| = x + y u + z v
  };
  PatchFormFactor unoccluded_;
  std::vector<Piece> pieces_;
  Vec3 normal_{0.0};
  double area_ = 0.0;
  std::vector<double> polygonAreas_;
  size_t sampleCount_ = 0;
};

}  // namespace radview
