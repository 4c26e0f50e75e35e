// A junction's lane neighbourhood must answer "which lane is this point inside" as project_to_lane
// with a heading does (the reference driver's junction rule relies on it instead of the map-wide
// search): the same lane, and the same place on it to rounding, at seeded random points and
// headings over every junction of the built-in maps and of san_francisco, and at the lanes'
// vertices and beside them heading along them.
#include "physics/map/lane_neighbourhood.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "physics/map/apollo_map_reader.hpp"
#include "physics/map/builtin_maps.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/road_map.hpp"
#include "tests/support/shared_dir.hpp"

namespace scenfuzz {
namespace {

struct Agreement {
  int compared = 0;  // points asked
  int inside = 0;    // of them, inside some lane
};

// project_to_lane's answer where it lies inside a lane, nothing otherwise: what lane_containing
// promises.
std::optional<LaneProjection> expected(const RoadMap& map, MapPoint point, double heading) {
  auto on = project_to_lane(map, point, heading);
  if (!on || !on->inside) return std::nullopt;
  return on;
}

void expect_same(const RoadMap& map, const LaneNeighbourhood& neighbourhood, MapPoint point,
                 double heading, Agreement& agreement) {
  auto want = expected(map, point, heading);
  auto got = lane_containing(map, neighbourhood, point, heading);
  ++agreement.compared;
  ASSERT_EQ(want.has_value(), got.has_value())
      << "at (" << point.x << ", " << point.y << ") heading " << heading;
  if (!want) return;
  ++agreement.inside;
  EXPECT_EQ(want->lane, got->lane) << "at (" << point.x << ", " << point.y << ")";
  // Within rounding: at a vertex two segments of the lane tie, and the first met is kept (the map
  // index meets them in its own order, the neighbourhood lane by lane).
  EXPECT_NEAR(want->s, got->s, 1e-9);
  EXPECT_NEAR(want->lateral, got->lateral, 1e-9);
  EXPECT_NEAR(want->distance, got->distance, 1e-9);
  EXPECT_TRUE(got->inside);
}

// Random points over the covered box with random headings, and points on and beside every
// centre-line vertex in the box heading along the lane (where overlapping junction lanes make the
// heading decide), for every junction of the map.
Agreement compare_on_junctions(const RoadMap& map, int points_per_junction) {
  Agreement agreement;
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> unit(0, 1);
  for (std::uint32_t j = 0; j < map.junctions().size(); ++j) {
    const LaneNeighbourhood neighbourhood = junction_neighbourhood(map, j, 10);
    if (map.junctions()[j].outline.empty()) continue;
    const MapPoint low = neighbourhood.low, high = neighbourhood.high;
    for (int k = 0; k < points_per_junction; ++k) {
      MapPoint p{low.x + unit(random) * (high.x - low.x), low.y + unit(random) * (high.y - low.y)};
      EXPECT_TRUE(covers(neighbourhood, p));
      expect_same(map, neighbourhood, p, (unit(random) * 2 - 1) * std::numbers::pi, agreement);
    }
    for (const NeighbourSegment& segment : neighbourhood.segments) {
      const Polyline& line = map.lane(segment.lane).centre_line;
      const MapPoint a = line.points()[segment.segment];
      const double heading = line.heading_at(line.arc_lengths()[segment.segment]);
      for (double side : {-1.0, 0.0, 1.0}) {
        const MapPoint p{a.x - std::sin(heading) * side, a.y + std::cos(heading) * side};
        if (covers(neighbourhood, p)) expect_same(map, neighbourhood, p, heading, agreement);
      }
    }
  }
  return agreement;
}

TEST(LaneNeighbourhoodTest, AnswersAsProjectToLaneOnEveryBuiltinJunction) {
  for (const std::string name : {"crossroads", "t_junction", "roundabout"}) {
    SCOPED_TRACE(name);
    const RoadMap map = build_road_map(generate_builtin_map(name, {}));
    ASSERT_FALSE(map.junctions().empty());
    Agreement agreement = compare_on_junctions(map, 3000);
    // The comparison means something only if many points are inside lanes, and some not.
    EXPECT_GT(agreement.inside, agreement.compared / 10);
    EXPECT_LT(agreement.inside, agreement.compared);
  }
}

TEST(LaneNeighbourhoodTest, AnswersAsProjectToLaneOnSanFranciscosJunctions) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const RoadMap map = build_road_map(
      read_apollo_map(test::shared_dir() / "maps" / "apollo" / "san_francisco" / "base_map.bin"));
  Agreement agreement = compare_on_junctions(map, 200);
  EXPECT_GT(agreement.inside, agreement.compared / 10);
}

TEST(LaneNeighbourhoodTest, HoldsOnlySegmentsThatCanContainAPointOfTheArea) {
  const RoadMap map = build_road_map(generate_builtin_map("crossroads", {}));
  const LaneNeighbourhood far = lane_neighbourhood(map, {5000, 5000}, {5010, 5010});
  EXPECT_TRUE(far.segments.empty());
  EXPECT_FALSE(covers(far, {0, 0}));
  EXPECT_TRUE(covers(far, {5005, 5000}));
  const LaneNeighbourhood centre = junction_neighbourhood(map, 0, 10);
  ASSERT_FALSE(centre.segments.empty());
  for (const NeighbourSegment& segment : centre.segments) {
    EXPECT_TRUE(segment.low.x <= centre.high.x && segment.high.x >= centre.low.x &&
                segment.low.y <= centre.high.y && segment.high.y >= centre.low.y)
        << map.lane(segment.lane).id << " segment " << segment.segment;
  }
}

TEST(LaneNeighbourhoodTest, AJunctionWithoutAnOutlineCoversNothing) {
  MapDescription description = generate_builtin_map("crossroads", {});
  ASSERT_FALSE(description.junctions.empty());
  description.junctions[0].outline.clear();
  const RoadMap map = build_road_map(std::move(description));
  const LaneNeighbourhood none = junction_neighbourhood(map, 0, 10);
  EXPECT_TRUE(none.segments.empty());
  EXPECT_FALSE(covers(none, {0, 0}));
}

}  // namespace
}  // namespace scenfuzz
