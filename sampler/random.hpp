// The one kind of random generator in scenfuzz: seeded, passed by reference, never global, and
// mapped to numbers by hand so that a seed gives the same draws with every standard library.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>

namespace scenfuzz {

// A seed for stream `stream` of a run seeded `seed` (SplitMix64 over both): evaluation i of a
// search draws from derive_seed(run seed, i), whatever thread runs it.
inline std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  std::uint64_t bits() { return engine_(); }
  // Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lower, double upper) { return lower + (upper - lower) * uniform(); }
  // Uniform in {0, ..., count - 1}; count > 0.
  std::size_t index(std::size_t count) {
    return static_cast<std::size_t>(uniform() * static_cast<double>(count)) % count;
  }
  bool chance(double probability) { return uniform() < probability; }
  // Standard normal by Box-Muller (one of the pair; the draws stay simple to reason about).
  double normal() {
    const double u = 1.0 - uniform();  // (0, 1]: log is finite
    return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * uniform());
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace scenfuzz
