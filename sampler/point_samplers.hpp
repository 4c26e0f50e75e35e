// Points of the unit cube [0,1]^d for the search to evaluate: uniform random, the Halton
// low-discrepancy sequence, and Latin hypercube designs. Deterministic for a given seed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sampler/random.hpp"

namespace scenfuzz {

using UnitPoint = std::vector<double>;

// Uniform in [0, 1)^dimensions.
UnitPoint uniform_point(std::size_t dimensions, Random& random);

// The Halton sequence in `dimensions` dimensions (bases: the first primes), each coordinate
// scrambled with an independent random permutation of the digits per digit position, drawn from
// `seed` (Matousek's random digit scrambling: it breaks the correlations plain Halton shows in
// higher dimensions). Point k of the sequence is point(k); index 0 is not the origin.
class HaltonSequence {
 public:
  HaltonSequence(std::size_t dimensions, std::uint64_t seed);
  UnitPoint point(std::uint64_t index) const;
  std::size_t dimensions() const { return bases_.size(); }

 private:
  std::vector<std::uint32_t> bases_;
  // permutations_[d][digit position][digit]: per dimension, per digit position (up to 64).
  std::vector<std::vector<std::vector<std::uint32_t>>> permutations_;
};

// `count` (< 2^53) points such that in every dimension each of the `count` equal slices of [0, 1)
// holds exactly one point (at a random place within it).
std::vector<UnitPoint> latin_hypercube(std::size_t count, std::size_t dimensions, Random& random);

}  // namespace scenfuzz
