// The cheap reach bound of a turned rectangle against the plain formula with std::cos and
// std::sin: never below it, and never more than a hair above it, on random and awkward headings.
#include "physics/collision/turned_reach.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace scenfuzz {
namespace {

void expect_tight_bound(double half_length, double half_width, double heading) {
  const double c = std::abs(std::cos(heading)), s = std::abs(std::sin(heading));
  const double exact_x = half_length * c + half_width * s;
  const double exact_y = half_length * s + half_width * c;
  const TurnedReach bound = turned_reach_bound(half_length, half_width, heading);
  const double slack = 2e-9 * (half_length + half_width);
  EXPECT_GE(bound.x, exact_x) << "heading " << heading;
  EXPECT_GE(bound.y, exact_y) << "heading " << heading;
  EXPECT_LE(bound.x, exact_x + slack) << "heading " << heading;
  EXPECT_LE(bound.y, exact_y + slack) << "heading " << heading;
}

TEST(TurnedReach, BoundsThePlainFormulaOnRandomHeadings) {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> heading(-10, 10), half(0.05, 10);
  for (int i = 0; i < 200'000; ++i) expect_tight_bound(half(random), half(random), heading(random));
}

TEST(TurnedReach, BoundsThePlainFormulaAtQuarterTurnsAndTheirNeighbours) {
  constexpr double kPi = std::numbers::pi;
  std::vector<double> headings;
  for (int k = -16; k <= 16; ++k) {
    const double quarter = k * kPi / 4;
    headings.push_back(quarter);
    headings.push_back(std::nextafter(quarter, 1e9));
    headings.push_back(std::nextafter(quarter, -1e9));
  }
  for (double heading : headings) expect_tight_bound(2.35, 0.925, heading);
}

TEST(TurnedReach, BoundsThePlainFormulaForHugeAndTinyHeadings) {
  for (double heading : {1e-300, -1e-17, 99999.9, -1e5, 1e5, 3e7, -1e300})
    expect_tight_bound(2.35, 0.925, heading);
}

}  // namespace
}  // namespace scenfuzz
