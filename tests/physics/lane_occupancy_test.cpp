// A lane follower looks only at the actors filed on the lanes of its route (and at loose ones),
// so the filing must put a vehicle on every lane its body or predicted body reaches, and leave
// every actor that does not keep to its lane loose, for the followers' geometric look.
#include "physics/simulation/lane_occupancy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "map_fixtures.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/predicted_points.hpp"
#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

struct Actor {
  TraceActorKind kind = TraceActorKind::vehicle;
  double x = 0, y = 0, heading = 0, speed = 0;
  std::int32_t lane = -1;
  double s = 0;
};

// Files `actors` (4.6 m x 1.9 m bodies) on the two-lane road and answers which lanes each is on.
class Filing {
 public:
  Filing() : map_(build_road_map(test::two_lane_road())), occupancy_(map_) {}

  LaneIndex lane(const char* id) const { return *map_.find_lane(id); }

  void file(const std::vector<Actor>& actors) {
    states_.clear();
    fixes_.clear();
    kinds_.clear();
    for (const Actor& actor : actors) {
      KinematicState state;
      state.x = actor.x;
      state.y = actor.y;
      state.heading = actor.heading;
      state.speed = actor.speed;
      states_.push_back(state);
      fixes_.push_back({actor.lane, actor.s});
      kinds_.push_back(actor.kind);
    }
    lengths_.assign(actors.size(), 4.6);
    widths_.assign(actors.size(), 1.9);
    predictor_.predict(states_, 1.5, predicted_);
    occupancy_.set_step({states_, &predictor_, fixes_, lengths_, widths_, kinds_, {}, 1.5});
  }

  std::vector<std::uint32_t> on(const char* id) const {
    std::vector<std::uint32_t> actors;
    occupancy_.append_on(lane(id), actors);
    return actors;
  }
  const std::vector<std::uint32_t>& loose() const { return occupancy_.loose(); }

 private:
  RoadMap map_;
  LaneOccupancy occupancy_;
  std::vector<KinematicState> states_;
  std::vector<LaneFix> fixes_;
  std::vector<TraceActorKind> kinds_;
  std::vector<double> lengths_, widths_;
  std::vector<MapPoint> predicted_;
  PointPredictor predictor_;
};

using Ids = std::vector<std::uint32_t>;

TEST(LaneOccupancy, AVehicleKeepingToItsLaneIsFiledOnItOnly) {
  Filing filing;
  const auto a = static_cast<std::int32_t>(filing.lane("a"));
  filing.file({{TraceActorKind::vehicle, 50, 0.2, 0, 10, a, 50}});
  EXPECT_EQ(filing.on("a"), Ids{0});
  EXPECT_EQ(filing.on("b"), Ids{});
  EXPECT_EQ(filing.on("a_next"), Ids{});
  EXPECT_EQ(filing.loose(), Ids{});
}

TEST(LaneOccupancy, AVehicleNearItsLanesEndIsFiledOnTheSuccessorsItWillReach) {
  Filing filing;
  const auto a = static_cast<std::int32_t>(filing.lane("a"));
  const auto a_next = static_cast<std::int32_t>(filing.lane("a_next"));
  // 15 m of travel in 1.5 s from 10 m before a's end: into a_next, not as far as the turn.
  filing.file({{TraceActorKind::vehicle, 90, 0, 0, 10, a, 90},
               // Just past a's end, its rear still on a.
               {TraceActorKind::vehicle, 101, 0, 0, 0, a_next, 1}});
  EXPECT_EQ(filing.on("a"), (Ids{0, 1}));
  EXPECT_EQ(filing.on("a_next"), (Ids{0, 1}));
  EXPECT_EQ(filing.on("turn"), Ids{});
  // 5 m before a_next's end, standing: its front reaches into the turn.
  filing.file({{TraceActorKind::vehicle, 146, 0, 0, 0, a_next, 46}});
  EXPECT_EQ(filing.on("turn"), Ids{0});
}

TEST(LaneOccupancy, AVehicleAcrossTheLaneLineOrTurningOutOfItsLaneIsLoose) {
  Filing filing;
  const auto a = static_cast<std::int32_t>(filing.lane("a"));
  filing.file({// Straddling the line between a and b.
               {TraceActorKind::vehicle, 50, 1.5, 0, 10, a, 50},
               // In the middle of a, turned 10 degrees towards b: in 1.5 s it is across the line.
               {TraceActorKind::vehicle, 60, 0, 10 * M_PI / 180, 10, a, 60},
               // The same, standing: it stays where it is, within a.
               {TraceActorKind::vehicle, 70, 0, 10 * M_PI / 180, 0, a, 70}});
  EXPECT_EQ(filing.loose(), (Ids{0, 1}));
  EXPECT_EQ(filing.on("a"), Ids{2});
  EXPECT_EQ(filing.on("b"), Ids{});
}

TEST(LaneOccupancy, TheEgoPedestriansObstaclesAndVehiclesOffTheLanesAreLoose) {
  Filing filing;
  const auto a = static_cast<std::int32_t>(filing.lane("a"));
  filing.file({{TraceActorKind::ego, 20, 0, 0, 10, a, 20},
               {TraceActorKind::pedestrian, 30, 0, 0, 1, a, 30},
               {TraceActorKind::obstacle, 40, 0, 0, 0, a, 40},
               {TraceActorKind::vehicle, 50, -10, 0, 10, -1, 0}});
  EXPECT_EQ(filing.loose(), (Ids{0, 1, 2, 3}));
  EXPECT_EQ(filing.on("a"), Ids{});
}

// In a whole run: a slow car changing into a follower's lane ahead of it is loose while it is
// across the line, and the follower, which looks by lane, brakes for it instead of driving into
// it.
TEST(LaneOccupancy, AFollowerBrakesForACarChangingIntoItsLane) {
  const std::string text =
      "ego = AV((\"east_1\"->400, , 0), (\"east_1\"->420));\n"
      "changer = Vehicle((\"east_1\"->60, , 5), , (\"east_0\"->500));\n"
      "follower = Vehicle((\"east_0\"->20, , 15), , (\"east_0\"->600));\n"
      "scenario = CreateScenario{load(\"straight?two_way=0&lanes=2\");\nego;\n{changer, "
      "follower};\n{};\n{};\n};\n";
  SimulationOptions options;
  options.duration = 30;
  options.target_reach = -1;
  auto run = test::simulate_text(text, options);
  ASSERT_TRUE(run.trace) << run.errors;
  for (const Collision& collision : run.trace->collisions)
    EXPECT_TRUE(collision.first == kEgo || collision.second == kEgo)
        << collision.first << " hit " << collision.second << " at " << collision.time;
  EXPECT_GT(test::closest_approach(*run.trace, 1, 2), 0.5);
}

}  // namespace
}  // namespace scenfuzz
