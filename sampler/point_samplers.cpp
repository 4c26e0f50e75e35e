// Uniform, scrambled Halton and Latin hypercube points of the unit cube. Every draw comes from the
// Random passed in (or seeded by the caller's seed), so a seed fixes the points.
#include "sampler/point_samplers.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace scenfuzz {
namespace {

// The largest double below 1: sums of digits and offsets that round up to 1 are pulled back
// here, so that every coordinate stays in [0, 1).
constexpr double below_one = 1.0 - 0x1.0p-53;

std::vector<std::uint32_t> first_primes(std::size_t count) {
  std::vector<std::uint32_t> primes;
  primes.reserve(count);
  for (std::uint32_t candidate = 2; primes.size() < count; ++candidate) {
    bool is_prime = true;
    for (const std::uint32_t prime : primes) {
      if (static_cast<std::uint64_t>(prime) * prime > candidate) break;
      if (candidate % prime == 0) {
        is_prime = false;
        break;
      }
    }
    if (is_prime) primes.push_back(candidate);
  }
  return primes;
}

// How many base-`base` digits the largest 64-bit index has: the digit positions that any index
// can reach, each of which gets its own permutation.
std::size_t digit_positions(std::uint32_t base) {
  std::size_t positions = 0;
  for (std::uint64_t remaining = std::numeric_limits<std::uint64_t>::max(); remaining > 0;
       remaining /= base) {
    ++positions;
  }
  return positions;
}

// Fisher-Yates over {0, ..., count - 1}, drawing with Random::index so that the permutation
// depends only on the seed and not on the standard library's shuffle.
template <typename Element>
std::vector<Element> random_permutation(std::size_t count, Random& random) {
  std::vector<Element> permutation(count);
  std::iota(permutation.begin(), permutation.end(), Element{0});
  for (std::size_t last = permutation.size(); last > 1; --last) {
    std::swap(permutation[last - 1], permutation[random.index(last)]);
  }
  return permutation;
}

}  // namespace

UnitPoint uniform_point(std::size_t dimensions, Random& random) {
  UnitPoint point(dimensions);
  for (double& coordinate : point) coordinate = random.uniform();
  return point;
}

HaltonSequence::HaltonSequence(std::size_t dimensions, std::uint64_t seed)
    : bases_(first_primes(dimensions)) {
  Random random(seed);
  permutations_.reserve(bases_.size());
  for (const std::uint32_t base : bases_) {
    // Leading zeros are permuted too (0 need not map to 0): that is what makes the scramble
    // move every point, including the first ones, rather than only their low-order digits.
    std::vector<std::vector<std::uint32_t>> per_position(digit_positions(base));
    for (auto& permutation : per_position) {
      permutation = random_permutation<std::uint32_t>(base, random);
    }
    permutations_.push_back(std::move(per_position));
  }
}

UnitPoint HaltonSequence::point(std::uint64_t index) const {
  // Plain Halton starts at index 1 (index 0 is the origin in every dimension); the wrap at the
  // largest index is harmless, as the scrambled image of 0 is an ordinary point.
  const std::uint64_t sequence_index = index + 1;
  UnitPoint point(bases_.size());
  std::vector<std::uint32_t> digits;
  for (std::size_t dimension = 0; dimension < bases_.size(); ++dimension) {
    const std::uint32_t base = bases_[dimension];
    const auto& per_position = permutations_[dimension];
    digits.assign(per_position.size(), 0);
    std::uint64_t remaining = sequence_index;
    for (std::size_t position = 0; remaining > 0; ++position) {
      digits[position] = static_cast<std::uint32_t>(remaining % base);
      remaining /= base;
    }
    // Horner from the least significant digit: each division scales all lower digits at once,
    // so the tiny terms are added while they are still large enough not to be lost.
    const double base_value = static_cast<double>(base);
    double value = 0.0;
    for (std::size_t position = per_position.size(); position-- > 0;) {
      value = (value + static_cast<double>(per_position[position][digits[position]])) / base_value;
    }
    point[dimension] = std::min(value, below_one);
  }
  return point;
}

std::vector<UnitPoint> latin_hypercube(std::size_t count, std::size_t dimensions, Random& random) {
  std::vector<UnitPoint> points(count, UnitPoint(dimensions));
  if (count == 0) return points;
  const double slice_count = static_cast<double>(count);
  for (std::size_t dimension = 0; dimension < dimensions; ++dimension) {
    const std::vector<std::size_t> slices = random_permutation<std::size_t>(count, random);
    for (std::size_t i = 0; i < count; ++i) {
      // Slice bounds by division (correctly rounded, so monotone in the slice): the upper bound
      // of one slice is bit for bit the lower bound of the next, and a point placed at
      // [lower, upper) in doubles lies in exactly one slice.
      const double lower = static_cast<double>(slices[i]) / slice_count;
      const double upper = static_cast<double>(slices[i] + 1) / slice_count;
      const double value = lower + random.uniform() * (upper - lower);
      points[i][dimension] = std::clamp(value, lower, std::nextafter(upper, 0.0));
    }
  }
  return points;
}

}  // namespace scenfuzz
