// The shortcuts the reference driver and the lane followers take to save instructions must not
// change an answer: outlines rejected by their bounding box, objects rejected unlocated as too far
// from the route, headings and states found by walking from a known segment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "physics/actors/path_pose.hpp"
#include "physics/ego/route_tracker.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/map_source.hpp"
#include "physics/map/polygon.hpp"

namespace scenfuzz {
namespace {

const MapSearchPath kNoSearchPath{};

// near_polygon as it was before its bounding-box test: every edge's distance, and the crossing
// number.
bool near_polygon_by_every_edge(MapPoint p, const std::vector<MapPoint>& polygon, double margin) {
  if (polygon.size() < 3) return false;
  auto cross = [](MapPoint o, MapPoint a, MapPoint b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const MapPoint& a = polygon[j];
    const MapPoint& b = polygon[i];
    if ((a.y > p.y) != (b.y > p.y) && (cross(a, b, p) > 0) == (b.y > a.y)) inside = !inside;
    if (distance_to_segment(p, a, b) <= margin) return true;
  }
  return inside;
}

TEST(NearPolygon, AnswersAsTestingEveryEdgeDoesAroundTurnedOutlinesAtUtmCoordinates) {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> unit(0, 1);
  int near = 0, far = 0;
  for (int outline = 0; outline < 50; ++outline) {
    // A crosswalk-like rectangle, turned, far from the origin.
    const MapPoint centre{552000 + 100 * unit(random), 4182000 + 100 * unit(random)};
    const double angle = 6.3 * unit(random), length = 3 + 10 * unit(random),
                 width = 2 + 3 * unit(random);
    const double c = std::cos(angle), s = std::sin(angle);
    std::vector<MapPoint> polygon;
    for (auto [u, v] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
      polygon.push_back({centre.x + c * u * length / 2 - s * v * width / 2,
                         centre.y + s * u * length / 2 + c * v * width / 2});
    for (int k = 0; k < 400; ++k) {
      const double margin = k % 4 == 0 ? 0.0 : 1.5;
      const MapPoint p{centre.x + (unit(random) - 0.5) * 30, centre.y + (unit(random) - 0.5) * 30};
      const bool expected = near_polygon_by_every_edge(p, polygon, margin);
      ASSERT_EQ(near_polygon(p, polygon, margin), expected) << outline << " " << k;
      (expected ? near : far) += 1;
    }
    // Exactly on the margin beyond a vertex along x (the box test's edge).
    const auto lowest_x = *std::min_element(polygon.begin(), polygon.end(),
                                            [](MapPoint a, MapPoint b) { return a.x < b.x; });
    const MapPoint on_margin{lowest_x.x - 1.5, lowest_x.y};
    EXPECT_EQ(near_polygon(on_margin, polygon, 1.5),
              near_polygon_by_every_edge(on_margin, polygon, 1.5));
  }
  EXPECT_GT(near, 1000) << "the points test both answers";
  EXPECT_GT(far, 1000);
  // A negative margin: inside still counts, whatever the box.
  const std::vector<MapPoint> square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  EXPECT_TRUE(near_polygon({0.5, 5}, square, -2));
  EXPECT_FALSE(near_polygon({-0.5, 5}, square, -2));
}

// A route through the crossroads with a left turn: straight, bending and straight again.
struct TurningRoute {
  RoadMap map = load_map("crossroads", kNoSearchPath);
  std::optional<LaneRoute> route =
      find_route(map, LanePosition{*map.find_lane("west_in_1"), 100, 0},
                 LanePosition{*map.find_lane("north_out_1"), 50, 0});
};

TEST(RouteTracker, RejectsUnlocatedOnlyPointsFartherThanTheDistanceFromEverySegment) {
  TurningRoute turning;
  ASSERT_TRUE(turning.route);
  RouteTracker tracker(turning.map, *turning.route, {}, 13.9);
  const Polyline& path = tracker.path();
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  int rejected = 0, kept = 0;
  for (double progress = 0; progress < tracker.length(); progress += 7) {
    tracker.update(path.point_at(progress));
    const PathWindow window = tracker.window(10, 60);
    for (int k = 0; k < 200; ++k) {
      const MapPoint on = path.point_at(tracker.progress() - 20 + 100 * unit(random));
      const MapPoint p{on.x + (unit(random) - 0.5) * 40, on.y + (unit(random) - 0.5) * 40};
      const double distance = 6 * unit(random);
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t segment = window.first; segment <= window.last; ++segment)
        nearest = std::min(nearest, path.project_to_segment(p, segment).distance);
      if (tracker.surely_farther(p, window, distance)) {
        ++rejected;
        ASSERT_GT(nearest, distance);
        auto at = tracker.locate(p, window, 1e9);
        ASSERT_TRUE(at);
        EXPECT_TRUE(at->beyond_end || std::abs(at->lateral) > distance - 1e-6);
      } else {
        ++kept;
      }
    }
  }
  EXPECT_GT(rejected, 500);
  EXPECT_GT(kept, 200);
  EXPECT_FALSE(tracker.surely_farther(path.point_at(tracker.progress()), tracker.window(0, 10), 0));
}

TEST(RouteTracker, HeadingFromALocatedSegmentIsTheHeadingAtItsArcLength) {
  TurningRoute turning;
  ASSERT_TRUE(turning.route);
  RouteTracker tracker(turning.map, *turning.route, {}, 13.9);
  const Polyline& path = tracker.path();
  for (double s = -1; s <= tracker.length() + 1; s += 0.37) {
    for (std::size_t hint : {std::size_t{0}, path.segment_count() / 2, path.segment_count() + 3})
      ASSERT_EQ(tracker.heading_at(s, hint), tracker.heading_at(s)) << s << " " << hint;
    const MapPoint beside = path.point_at(s);
    auto at = tracker.locate({beside.x + 0.8, beside.y - 0.6}, 0, tracker.length(), 1e9);
    ASSERT_TRUE(at);
    ASSERT_EQ(tracker.heading_at(at->s, at->segment), tracker.heading_at(at->s)) << s;
  }
}

TEST(StateOnPath, WalkingFromAHintGivesTheSameStateBitForBit) {
  TurningRoute turning;
  ASSERT_TRUE(turning.route);
  const Polyline path = route_path(turning.map, *turning.route);
  const std::vector<double> headings = segment_headings(path);
  std::size_t segment = 0;
  for (double s = -0.5; s <= path.length() + 0.5; s += 0.173) {
    const double clamped = std::clamp(s, 0.0, path.length());
    segment = path.segment_at(clamped);
    for (std::size_t hint : {segment, std::size_t{0}, path.segment_count() - 1}) {
      KinematicState walked = state_on_path(path, headings, s, 7, 0.5, hint);
      KinematicState searched = state_on_path(path, headings, s, 7, 0.5);
      ASSERT_EQ(walked.x, searched.x) << s;
      ASSERT_EQ(walked.y, searched.y) << s;
      ASSERT_EQ(walked.heading, searched.heading) << s;
      ASSERT_EQ(walked.yaw_rate, searched.yaw_rate) << s;
    }
  }
}

}  // namespace
}  // namespace scenfuzz
