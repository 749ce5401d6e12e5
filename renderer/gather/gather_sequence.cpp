#include "gather/gather_sequence.h"

#include "core/error.h"

#include <boost/random/sobol.hpp>

#include <string>

namespace radview {

GatherSequence::GatherSequence(int dimensions) : dimensions_(dimensions) {
  using Engine = boost::random::sobol_engine<uint32_t, 32>;
  constexpr unsigned kMaxDimensions = boost::random::default_sobol_table::max_dimension;
  if (dimensions < 1 || unsigned(dimensions) > kMaxDimensions)
    throw Error("final gather: " + std::to_string(dimensions) + " sample dimensions: the Sobol sequence has 1.." +
                std::to_string(kMaxDimensions));
  // Boost's engine steps through the points in Gray-code order and skips point 0: its n-th
  // point (from 0) is the one at index gray(n + 1). Index 2^b is gray(2^(b+1) - 1), the point
  // after 2^(b+1) - 2 others, and every other index is the XOR of those its bits name.
  Engine engine(static_cast<std::size_t>(dimensions));
  direction_.resize(size_t(kIndexBits) * size_t(dimensions));
  for (int bit = 0; bit < kIndexBits; ++bit) {
    engine.seed();
    engine.discard(uint64_t(dimensions) * ((uint64_t(2) << bit) - 2));
    for (int d = 0; d < dimensions; ++d) direction_[size_t(bit) * size_t(dimensions) + size_t(d)] = engine();
  }
}

std::vector<uint32_t> GatherSequence::point(uint32_t pass) const {
  std::vector<uint32_t> words(size_t(dimensions_), 0u);
  const uint32_t index = pass & ((1u << kIndexBits) - 1u);
  for (int bit = 0; bit < kIndexBits; ++bit)
    if (index >> bit & 1u)
      for (size_t d = 0; d < words.size(); ++d) words[d] ^= direction_[size_t(bit) * words.size() + d];
  return words;
}

GatherSequence::PixelPoint::PixelPoint(const std::vector<uint32_t>& point, uint64_t seed, uint64_t pixel, uint32_t pass,
                                       uint32_t run)
    : words_(point.data()),
      shifts_(SampleStream::forKey(seed, pixel, uint64_t(run) << 32 | uint64_t(pass >> kIndexBits))) {}

}  // namespace radview
