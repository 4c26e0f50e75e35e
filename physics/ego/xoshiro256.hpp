// The perception model's random bit generator: xoshiro256** (Blackman and Vigna, 2018), seeded
// by SplitMix64 from one 64-bit seed. Written out rather than taken from <random> because it is
// several times cheaper per draw than std::mt19937_64 (the perception draws about five numbers
// per detected object per step) and gives the same numbers with every compiler and library.
#pragma once

#include <array>
#include <cstdint>

namespace scenfuzz {

// SplitMix64: one step of the sequence that expands a seed into generator state (Vigna's
// recommended seeding for xoshiro: consecutive seeds give unrelated states).
inline std::uint64_t splitmix64(std::uint64_t& state) {
  state += 0x9e3779b97f4a7c15ULL;
  std::uint64_t z = state;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class Xoshiro256 {
 public:
  explicit Xoshiro256(std::uint64_t seed) {
    // SplitMix64 never yields four zero words in a row, so the state is never all zero.
    for (std::uint64_t& word : state_) word = splitmix64(seed);
  }
  // A given state (not all zero), for checking against the reference implementation.
  explicit Xoshiro256(const std::array<std::uint64_t, 4>& state) : state_(state) {}

  std::uint64_t operator()() {
    const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::array<std::uint64_t, 4> state_{};
};

// Uniform in [0, 1) from the top 53 bits.
inline double uniform01(Xoshiro256& random) {
  return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

}  // namespace scenfuzz
