#include "trace/patch_sampler.h"

#include "core/error.h"
#include "geom/polygon.h"

#include <algorithm>
#include <cmath>

namespace radview {

namespace {

constexpr uint64_t kStep = 0x9E3779B97F4A7C15ull;

uint64_t mixed(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

uint64_t SampleStream::next() { return mixed(state_ += kStep); }

uint64_t SampleStream::at(uint64_t i) const { return mixed(state_ + (i + 1) * kStep); }

SampleStream SampleStream::forKey(uint64_t a, uint64_t b, uint64_t c) {
  // Each key passes through the mixer before the next is added, so (a, b, c) and permutations
  // of it give unrelated streams.
  SampleStream mix(a);
  SampleStream second(mix.next() ^ b);
  SampleStream third(second.next() ^ c);
  return SampleStream(third.next());
}

PatchSampler::PatchSampler(const std::vector<Vec3>& corners, int samples)
    : PatchSampler(std::vector<std::vector<Vec3>>{corners}, samples) {}

PatchSampler::PatchSampler(const std::vector<std::vector<Vec3>>& polygons, int samples) : unoccluded_(polygons) {
  double largest = 0.0;
  for (const std::vector<Vec3>& polygon : polygons) {
    const double a = radview::area(polygon);
    polygonAreas_.push_back(a);
    area_ += a;
    if (a > largest) {
      largest = a;
      normal_ = unitNormal(polygon);
    }
  }
  if (!(area_ > 0.0) || normal_ == Vec3(0.0)) throw Error("a shooting patch has zero area");
  const int wanted = std::max(1, samples);
  auto gridSide = [&](double pieceArea) {
    return std::max(1, int(std::lround(std::sqrt(wanted * pieceArea / area_))));
  };
  for (uint32_t polygon = 0; polygon < polygons.size(); ++polygon) {
    const std::vector<Vec3>& corners = polygons[polygon];
    // A planar convex quad is one bilinear piece: its grid follows the quad's shape, which
    // stratifies better than two triangles would.
    if (corners.size() == 4 && isStrictlyConvex(corners) &&
        planarityError(corners) <= 1e-6 * glm::distance(corners[0], corners[2])) {
      Piece piece{corners[0], corners[1], corners[2], corners[3], true, polygon, gridSide(radview::area(corners))};
      // The Jacobian |dp/du x dp/dv| of a bilinear patch is linear in (u, v): the uv term of
      // the cross product is (b - a - c + d) x (d - a - c + b), a vector crossed with itself.
      // For a planar convex quad it is that vector's length along the normal; its values at
      // three corners of the parameter square fix it.
      const Vec3 n = unitNormal(corners);
      const Vec3 ab = corners[1] - corners[0], ad = corners[3] - corners[0];
      const double at00 = glm::dot(n, glm::cross(ab, ad));
      const double at10 = glm::dot(n, glm::cross(ab, corners[2] - corners[1]));
      const double at01 = glm::dot(n, glm::cross(corners[2] - corners[3], ad));
      piece.jacobian = {at00, at10 - at00, at01 - at00};
      pieces_.push_back(piece);
      continue;
    }
    for (const auto& t : triangulatePolygon(corners)) {
      const std::vector<Vec3> triangle = {corners[t[0]], corners[t[1]], corners[t[2]]};
      Piece piece{triangle[0], triangle[1], triangle[2], Vec3(0.0), false, polygon, 1};
      piece.k = gridSide(radview::area(triangle));
      piece.weight = radview::area(triangle) / (piece.k * piece.k);
      pieces_.push_back(piece);
    }
  }
  for (const Piece& piece : pieces_) sampleCount_ += size_t(piece.k) * piece.k;
}

void PatchSampler::draw(SampleStream& stream, std::vector<AreaSample>& out) const {
  const size_t first = out.size();
  out.resize(first + sampleCount_);
  draw(stream, out.data() + first);
}

void PatchSampler::draw(SampleStream& stream, AreaSample* out) const {
  size_t next = 0;
  for (const Piece& piece : pieces_) {
    const double cell = 1.0 / piece.k;
    for (int i = 0; i < piece.k; ++i)
      for (int j = 0; j < piece.k; ++j) {
        const double u = (i + stream.uniform()) * cell, v = (j + stream.uniform()) * cell;
        AreaSample& sample = out[next++];
        sample.polygon = piece.polygon;
        if (piece.quad) {
          // Bilinear p(u, v); the weight is the Jacobian times the cell's area.
          sample.position = (1.0 - v) * ((1.0 - u) * piece.a + u * piece.b) + v * ((1.0 - u) * piece.d + u * piece.c);
          const Vec3& J = piece.jacobian;
          sample.weight = (J.x + J.y * u + J.z * v) * cell * cell;
        } else {
          // The area-preserving map of the unit square onto a triangle (Shirley 1990):
          // equal cells map to equal areas, so each sample weighs area / k^2.
          const double s = std::sqrt(u);
          sample.position = (1.0 - s) * piece.a + s * (1.0 - v) * piece.b + s * v * piece.c;
          sample.weight = piece.weight;
        }
      }
  }
}

}  // namespace radview
