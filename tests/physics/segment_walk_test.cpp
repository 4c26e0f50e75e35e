// The look-ups the simulation uses in place of Polyline::segment_at and full projections must
// give exactly their answers: segment walks from a hint, galloping jumps, box bounds and the
// projections onto precomputed segment frames.
#include "physics/map/segment_walk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "physics/map/polyline_boxes.hpp"
#include "physics/map/segment_frames.hpp"
#include "tests/support/random_paths.hpp"

namespace scenfuzz {
namespace {

Polyline wiggly_path(std::mt19937_64& random, std::size_t points) {
  return test::random_path(random, points, 0.4);
}

TEST(SegmentWalk, SegmentAtFromAnyHintIsSegmentAt) {
  std::mt19937_64 random(7);
  Polyline path = wiggly_path(random, 200);
  std::uniform_real_distribution<double> along(-5, path.length() + 5);
  std::uniform_int_distribution<std::size_t> hint(0, path.segment_count() + 3);
  std::vector<double> probes = {0, path.length(), -1, path.length() + 1,
                                std::numeric_limits<double>::quiet_NaN()};
  for (double s : path.arc_lengths()) probes.push_back(s);  // exactly at the vertices
  for (int i = 0; i < 2000; ++i) probes.push_back(along(random));
  for (double s : probes)
    for (int j = 0; j < 5; ++j) {
      std::size_t from = hint(random);
      EXPECT_EQ(segment_at_from(path, s, from), path.segment_at(s))
          << "s " << s << " hint " << from;
    }
}

TEST(SegmentWalk, FirstSegmentReachingIsTheLinearScan) {
  std::mt19937_64 random(11);
  Polyline path = wiggly_path(random, 300);
  const auto& arc = path.arc_lengths();
  std::uniform_real_distribution<double> target(-5, path.length() + 20);
  for (std::size_t start = 0; start < path.segment_count(); start += 7)
    for (int i = 0; i < 50; ++i) {
      double s = i == 0 ? arc[start + 1] : target(random);
      std::size_t expected = start;
      while (expected < path.segment_count() && arc[expected + 1] < s) ++expected;
      EXPECT_EQ(first_segment_reaching(path, start, s), expected) << start << " " << s;
    }
}

// Walking from where the answer was at the last look must give the search's answer, from any
// start: near the answer, far from it (the walk gives up and searches), before the first segment
// allowed, past the end.
TEST(SegmentWalk, FirstSegmentReachingFromAnyStartIsTheSearchsAnswer) {
  std::mt19937_64 random(37);
  Polyline path = wiggly_path(random, 300);
  const auto& arc = path.arc_lengths();
  std::uniform_real_distribution<double> target(-5, path.length() + 20);
  std::uniform_int_distribution<std::size_t> anywhere(0, path.segment_count() + 3);
  std::uniform_int_distribution<int> nearby(-6, 6);
  for (std::size_t start = 0; start < path.segment_count(); start += 5)
    for (int i = 0; i < 60; ++i) {
      const double s = i == 0 ? arc[start + 1] : target(random);
      const std::size_t expected = first_segment_reaching(path, start, s);
      const auto near = static_cast<std::ptrdiff_t>(expected) + nearby(random);
      for (std::size_t from :
           {anywhere(random), static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, near)), start,
            std::size_t{0}})
        ASSERT_EQ(first_segment_reaching_from(path, start, s, from), expected)
            << start << " " << s << " from " << from;
    }
}

TEST(PolylineBoxes, BoxDistanceIsAtMostEverySegmentsOfItsRun) {
  std::mt19937_64 random(13);
  Polyline path = wiggly_path(random, 150);
  PolylineBoxes boxes(path);
  ASSERT_EQ(boxes.size(), (path.segment_count() + PolylineBoxes::kRun - 1) / PolylineBoxes::kRun);
  std::uniform_int_distribution<std::size_t> vertex(0, path.points().size() - 1);
  std::uniform_real_distribution<double> offset(-12, 12);
  int outside = 0;
  for (int i = 0; i < 3000; ++i) {
    const MapPoint& near_vertex = path.points()[vertex(random)];
    MapPoint point{near_vertex.x + offset(random), near_vertex.y + offset(random)};
    for (std::size_t box = 0; box < boxes.size(); ++box) {
      const double bound = std::sqrt(boxes.distance_squared(box, point));
      outside += bound > 0;
      for (std::size_t seg = box * PolylineBoxes::kRun;
           seg < std::min(path.segment_count(), (box + 1) * PolylineBoxes::kRun); ++seg)
        EXPECT_LE(bound, path.project_to_segment(point, seg).distance + 1e-9)
            << "point " << i << " box " << box << " segment " << seg;
    }
  }
  EXPECT_GT(outside, 1000);  // the bound is not trivially 0
}

// Group rejection is exact only if a group's box is never farther than one of its boxes, not
// even by rounding: checked as an inequality of the computed squares, with no tolerance.
TEST(PolylineBoxes, AGroupIsNoFartherThanAnyOfItsBoxesExactly) {
  std::mt19937_64 random(31);
  Polyline path = wiggly_path(random, 700);
  PolylineBoxes boxes(path);
  constexpr std::size_t group = PolylineBoxes::kGroup;
  std::uniform_int_distribution<std::size_t> vertex(0, path.points().size() - 1);
  std::uniform_real_distribution<double> offset(-40, 40);
  int apart = 0;
  for (int i = 0; i < 2000; ++i) {
    const MapPoint& near_vertex = path.points()[vertex(random)];
    MapPoint point{near_vertex.x + offset(random), near_vertex.y + offset(random)};
    for (std::size_t box = 0; box < boxes.size(); ++box) {
      const double group_squared = boxes.group_distance_squared(box / group, point);
      ASSERT_LE(group_squared, boxes.distance_squared(box, point))
          << "point " << i << " box " << box;
      apart += group_squared > 0;
    }
  }
  EXPECT_GT(apart, 10000);  // the bound is not trivially 0
}

TEST(PolylineBoxes, ABoxHoldsItsRunsVertices) {
  std::vector<MapPoint> straight;
  for (int i = 0; i <= 20; ++i) straight.push_back({static_cast<double>(i), 0.5 * i});
  Polyline path(straight);
  PolylineBoxes boxes(path);
  ASSERT_EQ(boxes.size(), 3u);  // segments 0-7, 8-15, 16-19
  EXPECT_EQ(boxes.low(1).x, 8);
  EXPECT_EQ(boxes.high(1).x, 16);
  EXPECT_EQ(boxes.high(2).y, 10);
  EXPECT_EQ(boxes.distance_squared(1, {12, 5}), 0);
  EXPECT_EQ(boxes.distance_squared(1, {12, 9}), 1);
}

TEST(SegmentFrames, DistanceSquaredIsTheProjectionsSquareBitForBit) {
  std::mt19937_64 random(19);
  Polyline path = wiggly_path(random, 60);
  SegmentFrames frames(path);
  std::uniform_real_distribution<double> offset(-15, 15);
  for (int i = 0; i < 1000; ++i) {
    const MapPoint& near_vertex = path.points()[static_cast<std::size_t>(i) % 60];
    MapPoint point{near_vertex.x + offset(random), near_vertex.y + offset(random)};
    std::size_t segment = static_cast<std::size_t>(i * 7) % path.segment_count();
    EXPECT_EQ(std::sqrt(frames.distance_squared(path, point, segment)),
              frames.project(path, point, segment).distance);
  }
}

TEST(SegmentFrames, ProjectionIsPolylinesBitForBit) {
  std::mt19937_64 random(17);
  Polyline path = wiggly_path(random, 120);
  SegmentFrames frames(path);
  std::uniform_int_distribution<std::size_t> vertex(0, path.points().size() - 1);
  std::uniform_real_distribution<double> offset(-15, 15);
  for (int i = 0; i < 2000; ++i) {
    const MapPoint& near_vertex = path.points()[vertex(random)];
    MapPoint point{near_vertex.x + offset(random), near_vertex.y + offset(random)};
    std::size_t segment = static_cast<std::size_t>(i) % path.segment_count();
    PolylineProjection expected = path.project_to_segment(point, segment);
    PolylineProjection got = frames.project(path, point, segment);
    // Bit for bit: EXPECT_EQ on doubles compares exactly.
    EXPECT_EQ(got.s, expected.s);
    EXPECT_EQ(got.lateral, expected.lateral);
    EXPECT_EQ(got.distance, expected.distance);
    EXPECT_EQ(got.segment, expected.segment);
  }
}

}  // namespace
}  // namespace scenfuzz
