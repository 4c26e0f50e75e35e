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

}  // namespace
}  // namespace scenfuzz
