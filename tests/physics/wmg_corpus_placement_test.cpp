// Issue 24: every actor of every WMG corpus file starts where the file puts it, at the lowest,
// middle and highest point of its space: on the lane it names (its lateral offset away from its
// centre line; a pedestrian may stand across its road), and, when placed relative to another
// actor, in the sector it names as seen from that actor (its position in the reference's frame:
// ahead or behind, left or right).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "lang/source_file.hpp"
#include "lang/wmg/wmg.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/scenario_setup.hpp"
#include "tests/lang/wmg_test_files.hpp"
#include "tests/support/parameter_points.hpp"

namespace scenfuzz {
namespace {

struct Pose {
  double x = 0, y = 0, heading = 0;
};

// Where `actor` stands in the frame of `reference`: metres ahead and metres to its left.
struct InFrame {
  double ahead = 0;
  double left = 0;
};

InFrame in_frame(const Pose& reference, const Pose& actor) {
  const double dx = actor.x - reference.x;
  const double dy = actor.y - reference.y;
  const double c = std::cos(reference.heading);
  const double s = std::sin(reference.heading);
  return {dx * c + dy * s, -dx * s + dy * c};
}

// Whether `where` lies in the WMG sector: F and R within 45 degrees of straight ahead or behind,
// the side sectors on their side (FSL ahead and left, SL left, RSL behind and left, ...).
bool in_sector(const InFrame& where, const std::string& sector) {
  constexpr double kBeside = 0.5;  // m: clearly to one side, not straddling the reference's axis
  const bool left = where.left > kBeside;
  const bool right = where.left < -kBeside;
  if (sector == "F") return where.ahead > 0 && std::abs(where.left) <= where.ahead;
  if (sector == "R") return where.ahead < 0 && std::abs(where.left) <= -where.ahead;
  if (sector == "FSL") return where.ahead > 0 && left;
  if (sector == "FSR") return where.ahead > 0 && right;
  if (sector == "SL") return left;
  if (sector == "SR") return right;
  if (sector == "RSL") return where.ahead < 0 && left;
  if (sector == "RSR") return where.ahead < 0 && right;
  ADD_FAILURE() << "unknown sector " << sector;
  return false;
}

// The lateral offset an actor's position asks for, at `values`.
double lateral_offset(const Position& position, const std::vector<double>& values) {
  return position.lateral ? evaluate(*position.lateral, values) : 0.0;
}

struct Placed {
  const Actor* actor = nullptr;
  Pose pose;
};

// Every actor of the scenario with its initial pose in `setup` (the ego first).
std::map<std::string, Placed> placed_actors(const ScenarioTemplate& scenario,
                                            const SimulationSetup& setup) {
  std::map<std::string, Placed> placed;
  placed[scenario.ego.name] = {
      &scenario.ego, {setup.ego_initial.x, setup.ego_initial.y, setup.ego_initial.heading}};
  std::vector<const Actor*> others;
  for (const Actor& actor : scenario.vehicles) others.push_back(&actor);
  for (const Actor& actor : scenario.pedestrians) others.push_back(&actor);
  for (const ScriptedActor& scripted : setup.actors)
    for (const Actor* actor : others)
      if (actor->name == scripted.name) {
        const KinematicState state = scripted.trajectory.state_at(0);
        placed[actor->name] = {actor, {state.x, state.y, state.heading}};
      }
  return placed;
}

// On the lane it names, its lateral offset from the centre line; a pedestrian on a side sector
// may stand on the far side of its road (place_relative): then that far from the nearest lane of
// the same road (ids sharing the arm or road prefix, `east_` of `east_in_0`).
void expect_on_named_lane(const RoadMap& map, const Placed& placed,
                          const std::vector<double>& values) {
  const Position& position = placed.actor->initial.position;
  if (position.lane.empty()) return;
  const auto lane = map.find_lane(position.lane);
  ASSERT_TRUE(lane) << placed.actor->name << ": " << position.lane;
  const MapPoint at{placed.pose.x, placed.pose.y};
  double distance = map.lane(*lane).centre_line.project(at).distance;
  const bool sided = position.relative_location.size() > 1;
  if (placed.actor->kind == ActorKind::pedestrian && sided) {
    const std::string road = position.lane.substr(0, position.lane.find('_') + 1);
    for (const Lane& other : map.lanes())
      if (!other.junction && other.id.starts_with(road))
        distance = std::min(distance, other.centre_line.project(at).distance);
  }
  EXPECT_NEAR(distance, std::abs(lateral_offset(position, values)), 0.05)
      << placed.actor->name << " is not on " << position.lane << "'s road";
}

TEST(WmgCorpusPlacement, EveryActorStartsOnItsLaneInTheSectorItsFileNames) {
  int relative = 0;
  for (const auto& entry : std::filesystem::directory_iterator(wmg::test::wmg_corpus_dir())) {
    if (entry.path().extension() != ".sdl") continue;
    std::optional<SourceFile> file = read_source_file(entry.path().string());
    ASSERT_TRUE(file);
    wmg::ParseResult result = wmg::parse(*file);
    ASSERT_TRUE(result.ok()) << format_diagnostics(*file, result.diagnostics);
    const ScenarioTemplate& scenario = result.scenario;
    const std::vector<std::vector<double>> points = test::corner_points(scenario);
    const char* const point_names[] = {"lowest", "middle", "highest"};
    for (std::size_t p = 0; p < points.size(); ++p) {
      SCOPED_TRACE(entry.path().filename().string() + " at its " + point_names[p] + " point");
      const std::vector<double>& values = points[p];
      const RoadMap map = load_scenario_map(scenario.map, map_search_path({}), values);
      Diagnostics diagnostics;
      const auto setup = prepare_simulation(scenario, values, map, 1, diagnostics);
      ASSERT_TRUE(setup) << format_diagnostics(*file, diagnostics);
      // Every turn goes where the file's lane connections lead (lane_links.hpp).
      EXPECT_EQ(format_diagnostics(*file, diagnostics).find("lane connections"), std::string::npos)
          << format_diagnostics(*file, diagnostics);
      const std::map<std::string, Placed> placed = placed_actors(scenario, *setup);
      for (const auto& [name, actor] : placed) {
        expect_on_named_lane(map, actor, values);
        const Position& position = actor.actor->initial.position;
        if (position.kind != PositionKind::relative) continue;
        ASSERT_TRUE(placed.contains(position.reference)) << name;
        const InFrame where = in_frame(placed.at(position.reference).pose, actor.pose);
        EXPECT_TRUE(in_sector(where, position.relative_location))
            << name << " is " << where.ahead << " m ahead of and " << where.left << " m left of "
            << position.reference << ", not in its " << position.relative_location;
        ++relative;
      }
    }
  }
  EXPECT_GE(relative, 20);
}

// A T-junction (R1 west, R2 east, the stem R3 south; two lanes a road, one each way by the
// connections) with the ego 30 m along R3.L1 and a car in `car_lane` at `sector`, 30 m ahead.
std::string junction_with_car(const std::string& car_lane, const std::string& sector) {
  std::string roads;
  for (int r = 1; r <= 3; ++r) {
    const std::string id = "R" + std::to_string(r);
    roads += wmg::test::road_text(
        id, 2, "Horizontal road geometry [Straight]", "Length [100] AND Lane width [3.5]",
        r == 1 ? "START" : "START: [J1]", r == 1 ? "END: [J1]" : "END", "48");
  }
  wmg::test::Parts parts;
  parts.scenery = wmg::test::scenery_with_roads(
      roads,
      "\nJ1: Junction type [T-Junction] as [T1]\nwhich has [Give way] connection control and [3] "
      "connections with [R1, R2, R3]\nAngles between roads [R1 -> R2, R2 -> R3] [180, 90]\n"
      "Road lane connections [R3.L1 -> R1.L2 + R2.L1, R1.L1 -> R2.L1 + R3.L2, R2.L2 -> R1.L2 + "
      "R3.L2]\nDimensions [Width: 10, Depth: 10]\n");
  parts.dynamics = "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R3.L1]\nAND Vehicle [Car] in [" +
                   car_lane + "] with a [Longitudinal] offset of [30] AND at relative position [" +
                   sector +
                   "] with relative heading angle [0] to [Ego]\nWHEN: [Ego] is [Going "
                   "Ahead]\nDO: AUTO\nEND\n";
  return parts.text();
}

// The car's pose and the ego's, as the simulation starts them.
std::pair<Pose, Pose> car_and_ego(const std::string& text) {
  SourceFile file("t.sdl", text);
  const wmg::ParseResult result = wmg::parse(file);
  EXPECT_TRUE(result.ok()) << format_diagnostics(file, result.diagnostics);
  const std::vector<double> values = test::corner_points(result.scenario).at(1);
  const RoadMap map = load_scenario_map(result.scenario.map, map_search_path({}), values);
  Diagnostics diagnostics;
  const auto setup = prepare_simulation(result.scenario, values, map, 1, diagnostics);
  EXPECT_TRUE(setup) << format_diagnostics(file, diagnostics);
  if (!setup) return {};
  const std::map<std::string, Placed> placed = placed_actors(result.scenario, *setup);
  return {placed.at("Car").pose, placed.at("Ego").pose};
}

// A lane out of the junction the reference drives into counts from the junction: on the oncoming
// lane of the reference's own road the actor stands beside it, offset ahead; on another arm's it
// stands as far past the junction as the reference plus the offset is before it.
TEST(WmgCorpusPlacement, AnActorOnALaneOutOfTheJunctionCountsItsPlaceFromTheJunction) {
  {
    SCOPED_TRACE("R3.L2, the oncoming lane of the ego's road");
    const auto [car, ego] = car_and_ego(junction_with_car("R3.L2", "FSL"));
    const InFrame where = in_frame(ego, car);
    EXPECT_NEAR(where.ahead, 30, 0.05);
    EXPECT_NEAR(where.left, 3.5, 0.05);
    EXPECT_NEAR(std::cos(car.heading - ego.heading), -1, 1e-6);  // oncoming
  }
  {
    SCOPED_TRACE("R1.L2, the lane the ego turns left into");
    const auto [car, ego] = car_and_ego(junction_with_car("R1.L2", "FSL"));
    // The junction is at the origin: the ego drives north towards it, the car west away from it.
    const double ego_before = -ego.y;
    const double car_past = -car.x;
    EXPECT_NEAR(std::cos(car.heading), -1, 1e-6);
    EXPECT_NEAR(ego_before - car_past, 30, 0.05);
  }
}

}  // namespace
}  // namespace scenfuzz
