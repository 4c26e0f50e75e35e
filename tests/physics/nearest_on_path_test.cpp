// nearest_on_path, what a lane follower asks of its path for every actor it looks at, must give
// exactly the answer of projecting onto every segment of the stretch: the nearest within reach,
// the first of equally near ones, bit for bit.
#include "physics/map/nearest_on_path.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "tests/support/random_paths.hpp"

namespace scenfuzz {
namespace {

Polyline winding_path(std::mt19937_64& random, std::size_t points) {
  return test::random_path(random, points, 0.5);
}

// The definition: every segment from `first` that starts by `until` projected, the smallest
// distance (the first of equal ones) if within reach.
PolylineProjection every_segment(const Polyline& path, const SegmentFrames& frames, MapPoint point,
                                 std::size_t first, double until, double reach) {
  PolylineProjection nearest;
  nearest.distance = std::numeric_limits<double>::infinity();
  for (std::size_t seg = first; seg < path.segment_count() && path.arc_lengths()[seg] <= until;
       ++seg) {
    PolylineProjection p = frames.project(path, point, seg);
    if (p.distance < nearest.distance) nearest = p;
  }
  if (nearest.distance > reach) nearest.distance = std::numeric_limits<double>::infinity();
  return nearest;
}

TEST(NearestOnPath, IsTheNearestOfEverySegmentBitForBit) {
  std::mt19937_64 random(23);
  Polyline path = winding_path(random, 400);
  PolylineBoxes boxes(path);
  SegmentFrames frames(path);
  std::uniform_int_distribution<std::size_t> start(0, path.segment_count() - 1), later(0, 60);
  std::uniform_real_distribution<double> offset(-10, 10), reach(0.5, 6), ahead(5, 120);
  int found = 0, none = 0;
  for (int i = 0; i < 20000; ++i) {
    std::size_t first = start(random);
    // Mostly near the stretch looked at, sometimes behind it or far beyond.
    const MapPoint& near_vertex =
        path.points()[std::min(first + later(random) - 5 * (i % 3 == 0), path.segment_count())];
    MapPoint point{near_vertex.x + offset(random), near_vertex.y + offset(random)};
    if (i % 10 == 0) point = near_vertex;  // exactly on a vertex: two segments equally near
    double until = path.arc_lengths()[first] + ahead(random);
    double r = reach(random);
    PolylineProjection expected = every_segment(path, frames, point, first, until, r);
    // Within rounding of the reach either answer is right; such points are not compared.
    if (std::abs(expected.distance - r) < 1e-9) continue;
    PolylineProjection got = nearest_on_path(path, boxes, frames, point, first, until, r);
    if (!std::isfinite(expected.distance)) {
      EXPECT_FALSE(std::isfinite(got.distance)) << "point " << i;
      ++none;
      continue;
    }
    ++found;
    EXPECT_EQ(got.segment, expected.segment) << "point " << i;
    EXPECT_EQ(got.distance, expected.distance) << "point " << i;
    EXPECT_EQ(got.s, expected.s) << "point " << i;
    EXPECT_EQ(got.lateral, expected.lateral) << "point " << i;
  }
  // The test means something only if both answers occur often.
  EXPECT_GT(found, 2000);
  EXPECT_GT(none, 2000);
}

// A lane follower makes its path's boxes and frames only as far as it reads (extend): made past
// the stretch's last segment, they give the answer of those made for the whole path, bit for bit.
TEST(NearestOnPath, BoxesAndFramesMadePastTheStretchGiveTheSameAnswer) {
  std::mt19937_64 random(29);
  Polyline path = winding_path(random, 700);
  PolylineBoxes all_boxes(path);
  SegmentFrames all_frames(path);
  std::uniform_int_distribution<std::size_t> start(0, path.segment_count() - 1), later(0, 60);
  std::uniform_real_distribution<double> offset(-6, 6), reach(0.5, 6), ahead(5, 120);
  constexpr std::size_t unit = PolylineBoxes::kRun * PolylineBoxes::kGroup;
  int found = 0;
  for (int i = 0; i < 5000; ++i) {
    const std::size_t first = start(random);
    const double until = path.arc_lengths()[first] + ahead(random);
    // As the follower makes them: whole groups through the segment holding `until`.
    const std::size_t last = path.segment_at(std::min(until, path.length()));
    const std::size_t made = std::min(path.segment_count(), (last / unit + 1) * unit);
    PolylineBoxes boxes;
    SegmentFrames frames;
    for (std::size_t k = unit; k < made; k += unit)
      boxes.extend(path, k);  // in steps, as it drives
    boxes.extend(path, made);
    frames.extend(path, made);
    ASSERT_EQ(boxes.segments(), made);
    const MapPoint& near_vertex =
        path.points()[std::min(first + later(random), path.segment_count())];
    const MapPoint point{near_vertex.x + offset(random), near_vertex.y + offset(random)};
    const double r = reach(random);
    const PolylineProjection expected =
        nearest_on_path(path, all_boxes, all_frames, point, first, until, r);
    const PolylineProjection got = nearest_on_path(path, boxes, frames, point, first, until, r);
    if (std::isfinite(expected.distance)) ++found;
    ASSERT_EQ(std::isfinite(got.distance), std::isfinite(expected.distance)) << "point " << i;
    if (!std::isfinite(expected.distance)) continue;
    EXPECT_EQ(got.segment, expected.segment) << "point " << i;
    EXPECT_EQ(got.distance, expected.distance) << "point " << i;
    EXPECT_EQ(got.s, expected.s) << "point " << i;
  }
  EXPECT_GT(found, 1000);
}

// A caller seeding the search with the distance to a segment of the stretch (a lane follower's
// segment from its last look at the actor) gets the same answer, bit for bit, also when that
// segment is far from the nearest or out of reach.
TEST(NearestOnPath, AKnownSegmentsDistanceChangesNothing) {
  std::mt19937_64 random(29);
  Polyline path = winding_path(random, 900);  // longer than a group of boxes several times
  PolylineBoxes boxes(path);
  SegmentFrames frames(path);
  std::uniform_int_distribution<std::size_t> start(0, path.segment_count() - 1), later(0, 60);
  std::uniform_real_distribution<double> offset(-10, 10), reach(0.5, 6), ahead(5, 300), extra(0, 3);
  int found = 0, seeded = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::size_t first = start(random);
    const MapPoint& near_vertex =
        path.points()[std::min(first + later(random), path.segment_count())];
    MapPoint point{near_vertex.x + offset(random), near_vertex.y + offset(random)};
    if (i % 10 == 0) point = near_vertex;
    const double until = path.arc_lengths()[first] + ahead(random);
    const double r = reach(random);
    // Some segment of the stretch, often the nearest's neighbourhood, and its distance or more.
    std::size_t last = first;
    while (last + 1 < path.segment_count() && path.arc_lengths()[last + 1] <= until) ++last;
    std::uniform_int_distribution<std::size_t> in_stretch(first, last);
    const PolylineProjection plain = nearest_on_path(path, boxes, frames, point, first, until, r);
    std::size_t seed = in_stretch(random);
    if (i % 2 == 0 && std::isfinite(plain.distance)) seed = std::min(last, plain.segment + i % 5);
    const double known =
        std::sqrt(frames.distance_squared(path, point, seed)) + (i % 3 == 0 ? extra(random) : 0.0);
    const PolylineProjection got =
        nearest_on_path(path, boxes, frames, point, first, until, r, known);
    seeded += known < r;
    if (!std::isfinite(plain.distance)) {
      EXPECT_FALSE(std::isfinite(got.distance)) << "point " << i;
      continue;
    }
    ++found;
    EXPECT_EQ(got.segment, plain.segment) << "point " << i;
    EXPECT_EQ(got.distance, plain.distance) << "point " << i;
    EXPECT_EQ(got.s, plain.s) << "point " << i;
    EXPECT_EQ(got.lateral, plain.lateral) << "point " << i;
  }
  EXPECT_GT(found, 2000);
  EXPECT_GT(seeded, 2000);  // the seed was tighter than the reach often enough to matter
}

TEST(NearestOnPath, LooksOnlyFromFirstToUntil) {
  std::vector<MapPoint> straight;
  for (int i = 0; i <= 40; ++i) straight.push_back({static_cast<double>(i), 0});
  Polyline path(straight);
  PolylineBoxes boxes(path);
  SegmentFrames frames(path);
  // Beside metre 30: found from the start with room enough ahead, not when `until` stops short
  // (segments starting after it are not looked at) nor from beyond it.
  PolylineProjection near = nearest_on_path(path, boxes, frames, {30.5, 1}, 0, 35, 2);
  EXPECT_EQ(near.segment, 30u);
  EXPECT_EQ(near.s, 30.5);
  EXPECT_EQ(near.lateral, 1);
  EXPECT_EQ(nearest_on_path(path, boxes, frames, {30.5, 1}, 0, 30, 2).segment, 30u);
  // Up to segment 28 (starting at 28 m): its end, 1.80 m away, is the nearest.
  EXPECT_EQ(nearest_on_path(path, boxes, frames, {30.5, 1}, 0, 28, 2).segment, 28u);
  EXPECT_FALSE(std::isfinite(nearest_on_path(path, boxes, frames, {30.5, 1}, 0, 27.5, 2).distance));
  // From segment 31 on, the nearest is segment 31's start, 1.118 m away.
  PolylineProjection later = nearest_on_path(path, boxes, frames, {30.5, 1}, 31, 40, 2);
  EXPECT_EQ(later.segment, 31u);
  EXPECT_EQ(later.s, 31);
  EXPECT_FALSE(
      std::isfinite(nearest_on_path(path, boxes, frames, {30.5, 1}, 31, 40, 1.1).distance));
  EXPECT_FALSE(std::isfinite(nearest_on_path(path, boxes, frames, {30.5, 3}, 0, 40, 2).distance));
}

double point_segment_distance(MapPoint p, MapPoint a, MapPoint b) {
  const double dx = b.x - a.x, dy = b.y - a.y, squared = dx * dx + dy * dy;
  const double t =
      squared > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / squared, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// The distance between the lines a-b and c-d: 0 where they cross, else that of the nearest end
// point to the other line.
double segment_distance(MapPoint a, MapPoint b, MapPoint c, MapPoint d) {
  auto side = [](MapPoint p, MapPoint q, MapPoint r) {
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
  };
  const double s1 = side(a, b, c), s2 = side(a, b, d), s3 = side(c, d, a), s4 = side(c, d, b);
  if (((s1 < 0 && s2 > 0) || (s1 > 0 && s2 < 0)) && ((s3 < 0 && s4 > 0) || (s3 > 0 && s4 < 0)))
    return 0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d),
                   point_segment_distance(c, a, b), point_segment_distance(d, a, b)});
}

// surely_clear_of rules a line out (a lane follower then searches none of its points): it must
// never do so for a line that comes within reach of a segment of the stretch, which the searches
// would find. Paths winding back on themselves, lines of up to 25 m (an actor's way in 1.5 s) near
// the stretch, boxes made for the whole path or only its start.
TEST(SurelyClearOf, NeverRulesOutALineWithinReachOfTheStretch) {
  std::mt19937_64 random(31);
  Polyline path = winding_path(random, 500);
  PolylineBoxes all_boxes(path), first_boxes;
  first_boxes.extend(path, 2 * PolylineBoxes::kRun * PolylineBoxes::kGroup);
  SegmentFrames frames(path);
  std::uniform_int_distribution<std::size_t> start(0, path.segment_count() - 1), later(0, 60);
  std::uniform_real_distribution<double> offset(-12, 12), way(-25, 25), reach(0.5, 6),
      ahead(5, 120);
  int clear = 0, within = 0;
  for (int i = 0; i < 20000; ++i) {
    const PolylineBoxes& boxes = i % 4 == 0 ? first_boxes : all_boxes;
    const std::size_t first = std::min(start(random), boxes.segments() - 1);
    const MapPoint& near_vertex =
        path.points()[std::min(first + later(random), path.segment_count())];
    const MapPoint a{near_vertex.x + offset(random), near_vertex.y + offset(random)};
    const MapPoint b = i % 5 == 0 ? a : MapPoint{a.x + way(random), a.y + way(random)};
    const double until = path.arc_lengths()[first] + ahead(random), r = reach(random);
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t seg = first; seg < boxes.segments() && path.arc_lengths()[seg] <= until; ++seg)
      nearest =
          std::min(nearest, segment_distance(a, b, path.points()[seg], path.points()[seg + 1]));
    if (!surely_clear_of(path, boxes, a, b, first, until, r)) {
      within += nearest <= r;
      continue;
    }
    ++clear;
    ASSERT_GT(nearest, r) << "line " << i;
    // And so the search finds nothing from any point of it.
    for (double f : {0.0, 0.37, 1.0}) {
      const MapPoint p{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
      EXPECT_FALSE(std::isfinite(nearest_on_path(path, boxes, frames, p, first, until, r).distance))
          << "line " << i;
    }
  }
  // Both answers often: the test means something, and the boxes rule out many lines.
  EXPECT_GT(clear, 3000);
  EXPECT_GT(within, 3000);
}

TEST(SurelyClearOf, ALineCrossingTheStretchBetweenItsEndsIsNotClear) {
  std::vector<MapPoint> straight;
  for (int i = 0; i <= 40; ++i) straight.push_back({static_cast<double>(i), 0});
  Polyline path(straight);
  PolylineBoxes boxes(path);
  // From 10 m on one side to 10 m on the other: neither end is within reach, the line is.
  EXPECT_FALSE(surely_clear_of(path, boxes, {20, -10}, {20, 10}, 0, 40, 2));
  EXPECT_TRUE(surely_clear_of(path, boxes, {20, 5}, {30, 10}, 0, 40, 2));
  // Beyond `until` (the boxes of segments starting after it are not looked at)...
  EXPECT_TRUE(surely_clear_of(path, boxes, {36, -10}, {36, 10}, 0, 15, 2));
  // ...and behind `first`.
  EXPECT_TRUE(surely_clear_of(path, boxes, {2, -10}, {2, 10}, 24, 40, 2));
}

}  // namespace
}  // namespace scenfuzz
