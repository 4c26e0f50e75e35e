// Arc-length polylines: construction, evaluation and projection.
#include "physics/map/polyline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
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

}  // namespace
}  // namespace scenfuzz
