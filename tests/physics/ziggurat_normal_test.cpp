// The perception's random numbers: xoshiro256** against its reference outputs, SplitMix64
// seeding, and the ziggurat's standard normals against the normal distribution (moments, tail
// frequencies and a chi-square over bins), with fixed seeds.
#include "physics/ego/ziggurat_normal.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "physics/ego/xoshiro256.hpp"

namespace scenfuzz {
namespace {

TEST(Xoshiro256, MatchesTheReferenceImplementation) {
  // Outputs of Blackman and Vigna's xoshiro256starstar.c from the state {1, 2, 3, 4}.
  Xoshiro256 random(std::array<std::uint64_t, 4>{1, 2, 3, 4});
  EXPECT_EQ(random(), 11520u);
  EXPECT_EQ(random(), 0u);
  EXPECT_EQ(random(), 1509978240u);
  EXPECT_EQ(random(), 1215971899390074240u);
}

TEST(Xoshiro256, SeedsThroughSplitMix64) {
  std::uint64_t state = 0;
  EXPECT_EQ(splitmix64(state), 0xe220a8397b1dcdafULL);  // SplitMix64's first output from 0
  // Same seed, same stream; a neighbouring seed, another one.
  Xoshiro256 a(7), b(7), c(8);
  for (int i = 0; i < 100; ++i) {
    const std::uint64_t value = a();
    EXPECT_EQ(value, b());
    EXPECT_NE(value, c());
  }
}

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

std::vector<double> draws(std::uint64_t seed, int count) {
  Xoshiro256 random(seed);
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) values.push_back(standard_normal(random));
  return values;
}

TEST(ZigguratNormal, MomentsAreThoseOfAStandardNormal) {
  const int n = 1'000'000;
  double sum = 0, sum2 = 0, sum3 = 0, sum4 = 0;
  for (double x : draws(1, n)) {
    sum += x;
    sum2 += x * x;
    sum3 += x * x * x;
    sum4 += x * x * x * x;
  }
  // Standard errors at n = 1e6: mean 0.001, variance 0.0014, third moment 0.0039, fourth 0.0099.
  EXPECT_NEAR(sum / n, 0, 0.005);
  EXPECT_NEAR(sum2 / n, 1, 0.007);
  EXPECT_NEAR(sum3 / n, 0, 0.02);
  EXPECT_NEAR(sum4 / n, 3, 0.05);
}

TEST(ZigguratNormal, TailsHaveTheRightWeightIncludingBeyondTheBaseLayer) {
  const int n = 2'000'000;
  int beyond_1 = 0, beyond_2 = 0, beyond_tail = 0, negative_tail = 0;
  for (double x : draws(2, n)) {
    beyond_1 += std::abs(x) > 1;
    beyond_2 += std::abs(x) > 2;
    beyond_tail += std::abs(x) > 3.5;  // drawn by the tail method (base layer edge 3.44)
    negative_tail += x < -3.5;
  }
  auto expected = [&](double t) { return 2 * n * normal_cdf(-t); };
  // Within 5 standard deviations of the binomial counts.
  auto tolerance = [&](double t) { return 5 * std::sqrt(expected(t)); };
  EXPECT_NEAR(beyond_1, expected(1), tolerance(1));
  EXPECT_NEAR(beyond_2, expected(2), tolerance(2));
  EXPECT_NEAR(beyond_tail, expected(3.5), tolerance(3.5));
  EXPECT_NEAR(negative_tail, expected(3.5) / 2, 5 * std::sqrt(expected(3.5) / 2));
}

TEST(ZigguratNormal, FitsTheNormalOverFineBins) {
  // 64 equal-probability bins: a chi-square with 63 degrees of freedom (mean 63, sd 11.2).
  const int n = 1'000'000, bins = 64;
  std::vector<int> counts(bins, 0);
  for (double x : draws(3, n)) {
    const auto bin = static_cast<int>(normal_cdf(x) * bins);
    ++counts[static_cast<std::size_t>(std::min(bin, bins - 1))];
  }
  const double expected = static_cast<double>(n) / bins;
  double chi_square = 0;
  for (int count : counts) chi_square += (count - expected) * (count - expected) / expected;
  EXPECT_LT(chi_square, 120);  // p < 1e-6 under the null
}

}  // namespace
}  // namespace scenfuzz
