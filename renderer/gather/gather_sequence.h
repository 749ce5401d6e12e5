#pragma once
// The numbers the final gather's estimator draws (eq. 9.9, final_gather.h), stratified across
// passes: pass i of every pixel takes point i of one Sobol sequence (Boost.Random's, Joe and
// Kuo's direction numbers), and each pixel XORs every coordinate with its own random word (a
// random digital shift). The shift keeps the sequence's nets: the first 2^k passes of the first
// two coordinates put one point in each of 2^k strata of any shape 2^-a x 2^-b, a + b = k,
// wherever the pixel's shift moves them; every point is still uniform on [0, 1)^d, so the
// estimate stays unbiased, and neighbouring pixels' errors are unrelated. For an integrand
// that is smooth apart from a few edges (a shadow, a silhouette) the error then falls faster
// than the 1/sqrt(spp) of independent samples.
#include "trace/patch_sampler.h"

#include <cstdint>
#include <vector>

namespace radview {

class GatherSequence {
 public:
  // Throws Error when `dimensions` is outside 1..the direction numbers Boost holds (3667).
  explicit GatherSequence(int dimensions);
  int dimensions() const { return dimensions_; }

  // Pass `pass`'s point before any shift, coordinate d as the word d / 2^32: the same for every
  // pixel, so a pass forms it once. Indices 2^18 apart take the same point (PixelPoint shifts
  // passes that far apart differently).
  std::vector<uint32_t> point(uint32_t pass) const;

  // One pixel's coordinates of a pass's point, for gather `seed` and its independent run `run`
  // (each run shifts the same points by words of its own, so runs are independent estimates).
  class PixelPoint {
   public:
    // `point` (GatherSequence::point(pass)) must outlive this.
    PixelPoint(const std::vector<uint32_t>& point, uint64_t seed, uint64_t pixel, uint32_t pass, uint32_t run = 0);
    double operator()(int dimension) const {  // in [0, 1)
      return (*this)(dimension, dimension);
    }
    // Word `word` of the point under coordinate `dimension`'s shift: another index's point in
    // that coordinate, appended to the words, keeps the joint strata of the shifted sequence.
    double operator()(int word, int dimension) const {
      return double(words_[word] ^ uint32_t(shifts_.at(uint64_t(dimension)) >> 32)) * 0x1.0p-32;
    }

   private:
    const uint32_t* words_;
    SampleStream shifts_;  // word d of the pixel's shift is the high half of its number d
  };

 private:
  static constexpr int kIndexBits = 18;
  int dimensions_;
  std::vector<uint32_t> direction_;  // [bit * dimensions + dimension]: the point at index 2^bit
};

}  // namespace radview
