// Arc-length polylines: construction, evaluation and projection.
#include "physics/map/polyline.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace scenfuzz {
namespace {

TEST(Polyline, ArcLengthsDropRepeatedPoints) {
  std::vector<MapPoint> points{{0, 0}, {3, 4}, {3, 4}, {3, 14}};
  Polyline line(points);
  EXPECT_EQ(line.points().size(), 3u);
  EXPECT_DOUBLE_EQ(line.length(), 15);
  EXPECT_EQ(line.arc_lengths(), (std::vector<double>{0, 5, 15}));
}

TEST(Polyline, RejectsDegenerateInput) {
  std::vector<MapPoint> one{{1, 1}};
  std::vector<MapPoint> same{{1, 1}, {1, 1}};
  std::vector<MapPoint> not_finite{{0, 0}, {NAN, 1}};
  EXPECT_THROW(Polyline{one}, std::invalid_argument);
  EXPECT_THROW(Polyline{same}, std::invalid_argument);
  EXPECT_THROW(Polyline{not_finite}, std::invalid_argument);
}

TEST(Polyline, PointAndHeadingAlongTheLine) {
  std::vector<MapPoint> points{{0, 0}, {10, 0}, {10, 10}};
  Polyline line(points);
  EXPECT_EQ(line.point_at(5), (MapPoint{5, 0}));
  EXPECT_EQ(line.point_at(15), (MapPoint{10, 5}));
  EXPECT_EQ(line.point_at(-3), (MapPoint{0, 0}));    // clamped
  EXPECT_EQ(line.point_at(99), (MapPoint{10, 10}));  // clamped
  EXPECT_DOUBLE_EQ(line.heading_at(5), 0);
  EXPECT_DOUBLE_EQ(line.heading_at(10), std::numbers::pi / 2);  // a vertex: the next segment
  EXPECT_DOUBLE_EQ(line.heading_at(20), std::numbers::pi / 2);
}

TEST(Polyline, ProjectionGivesArcLengthAndSignedOffset) {
  std::vector<MapPoint> points{{0, 0}, {10, 0}, {10, 10}};
  Polyline line(points);
  PolylineProjection left = line.project({4, 2});
  EXPECT_DOUBLE_EQ(left.s, 4);
  EXPECT_DOUBLE_EQ(left.lateral, 2);
  EXPECT_DOUBLE_EQ(left.distance, 2);
  PolylineProjection right = line.project({12, 7});  // right of the northbound segment
  EXPECT_DOUBLE_EQ(right.s, 17);
  EXPECT_DOUBLE_EQ(right.lateral, -2);
  PolylineProjection beyond = line.project({-3, 4});  // before the start: distance to (0, 0)
  EXPECT_DOUBLE_EQ(beyond.s, 0);
  EXPECT_DOUBLE_EQ(beyond.distance, 5);
}

TEST(AngleDifference, WrapsIntoHalfOpenRange) {
  EXPECT_NEAR(angle_difference(0.1, 2 * std::numbers::pi - 0.1), 0.2, 1e-12);
  EXPECT_NEAR(angle_difference(-std::numbers::pi, std::numbers::pi), 0, 1e-12);
  EXPECT_NEAR(angle_difference(std::numbers::pi, 0), std::numbers::pi, 1e-12);
  EXPECT_NEAR(angle_difference(-std::numbers::pi, 0), std::numbers::pi, 1e-12);
}

// The shortcut for differences already in range gives what remainder gives, bit for bit: at the
// ends of the range, an ulp inside and outside them, and at random.
TEST(AngleDifference, EqualsTheRemainderDefinitionExactly) {
  const double pi = std::numbers::pi;
  auto by_remainder = [&](double a, double b) {
    double difference = std::remainder(a - b, 2 * pi);
    if (difference <= -pi) difference += 2 * pi;
    return difference;
  };
  std::vector<double> angles = {0.0, -0.0, pi, -pi, 2 * pi, -2 * pi, 3 * pi, 1e-300, 1e6};
  for (double edge : {pi, -pi})
    for (double direction : {-10.0, 10.0}) angles.push_back(std::nextafter(edge, direction));
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> wide(-20, 20);
  for (int i = 0; i < 10000; ++i) angles.push_back(wide(random));
  for (double a : angles)
    for (double b : {0.0, 0.5, -3.0, pi}) {
      const double expected = by_remainder(a, b), got = angle_difference(a, b);
      EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(expected))
          << a << " - " << b;
    }
}

// project skips segments whose midpoint is out of reach; its answer must stay the first nearest
// segment's projection, bit for bit, also at UTM-sized coordinates and for points on the line.
TEST(Polyline, ProjectIsTheFirstNearestSegmentsProjectionBitForBit) {
  std::mt19937_64 random(29);
  std::uniform_real_distribution<double> length(0.05, 20.0), turn(-1.2, 1.2), offset(-30, 30);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<MapPoint> points{{553000.0 + trial, 4181700.0 - trial}};
    double heading = turn(random);
    for (int i = 0; i < 60; ++i) {
      heading += turn(random);
      const double ds = length(random);
      points.push_back(
          {points.back().x + ds * std::cos(heading), points.back().y + ds * std::sin(heading)});
    }
    Polyline line(points);
    for (int q = 0; q < 50; ++q) {
      MapPoint p = line.point_at(std::uniform_real_distribution<double>(0, line.length())(random));
      if (q % 2 == 1) p = {p.x + offset(random), p.y + offset(random)};
      PolylineProjection expected;
      expected.distance = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < line.segment_count(); ++k) {
        PolylineProjection candidate = line.project_to_segment(p, k);
        if (candidate.distance < expected.distance) expected = candidate;
      }
      PolylineProjection got = line.project(p);
      ASSERT_EQ(got.segment, expected.segment);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(got.s), std::bit_cast<std::uint64_t>(expected.s));
      ASSERT_EQ(std::bit_cast<std::uint64_t>(got.distance),
                std::bit_cast<std::uint64_t>(expected.distance));
      ASSERT_EQ(std::bit_cast<std::uint64_t>(got.lateral),
                std::bit_cast<std::uint64_t>(expected.lateral));
    }
  }
}

}  // namespace
}  // namespace scenfuzz
