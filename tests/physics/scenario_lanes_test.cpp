// The lanes real scenario files name exist in their maps: every lane position in the shared
// examples (written by others for Apollo/LGSVL) and in our seed corpus resolves to a pose on its
// map at the lowest, middle and highest values of its parameters, and every actor that starts
// and ends on lanes has a route between them.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/source_file.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/map_source.hpp"
#include "tests/support/parameter_points.hpp"
#include "tests/support/shared_dir.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

fs::path corpus_dir() {
  return fs::path(SCENFUZZ_TEST_DATA_DIR).parent_path().parent_path().parent_path() / "corpora";
}

std::vector<fs::path> scenario_files(const fs::path& folder) {
  std::vector<fs::path> files;
  if (!fs::is_directory(folder)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    auto extension = entry.path().extension();
    if (extension == ".avu" || extension == ".scenest") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

using test::corner_points;

struct NamedState {
  std::string where;
  const State* state;
};

std::vector<NamedState> states_of(const Actor& actor) {
  std::vector<NamedState> states{{actor.name + ".init", &actor.initial}};
  for (std::size_t i = 0; i < actor.motion.states.size(); ++i)
    states.push_back(
        {actor.name + ".waypoint[" + std::to_string(i) + "]", &actor.motion.states[i]});
  if (actor.target) states.push_back({actor.name + ".target", &*actor.target});
  return states;
}

class ScenarioLanes : public ::testing::Test {
 protected:
  // Null for a map that is not available here (CARLA towns), recorded in `unavailable_maps_`.
  const RoadMap* map_for(const ScenarioTemplate& scenario, std::span<const double> values) {
    std::string key = scenario.map.name;
    for (const NamedValue& parameter : scenario.map.parameters)
      key += "&" + parameter.name + "=" + std::to_string(evaluate(parameter.value, values));
    auto found = maps_.find(key);
    if (found == maps_.end()) {
      MapSearchPath path{{test::shared_dir() / "maps" / "apollo"}};
      std::unique_ptr<RoadMap> map;
      try {
        map = std::make_unique<RoadMap>(load_scenario_map(scenario.map, path, values));
      } catch (const MapError&) {
        unavailable_maps_.insert(scenario.map.name);
      }
      found = maps_.emplace(key, std::move(map)).first;
    }
    return found->second.get();
  }

  // Checks one file; returns how many lane positions it has.
  int check_file(const fs::path& file) {
    SCOPED_TRACE(file.string());
    std::optional<SourceFile> source = read_source_file(file.string());
    EXPECT_TRUE(source);
    if (!source) return 0;
    avunit::ParseResult parsed = avunit::parse(*source);
    EXPECT_TRUE(parsed.ok());
    const ScenarioTemplate& scenario = parsed.scenario;
    if (!scenario.has_scenario) return 0;
    int lane_positions = 0;
    for (const std::vector<double>& values : corner_points(scenario)) {
      const RoadMap* found_map = map_for(scenario, values);
      if (!found_map) continue;
      const RoadMap& map = *found_map;
      std::vector<const Actor*> actors{&scenario.ego};
      for (const Actor& actor : scenario.vehicles) actors.push_back(&actor);
      for (const Actor& actor : scenario.pedestrians) actors.push_back(&actor);
      for (const Actor* actor : actors) {
        std::optional<LanePosition> previous;
        for (const NamedState& named : states_of(*actor)) {
          const Position& position = named.state->position;
          if (position.kind != PositionKind::lane) continue;
          ++lane_positions;
          auto lane = map.find_lane(position.lane);
          EXPECT_TRUE(lane) << named.where << ": lane '" << position.lane << "' is not in map "
                            << map.name();
          if (!lane) continue;
          double s = evaluate(position.s, values);
          double lateral = position.lateral ? evaluate(*position.lateral, values) : 0.0;
          auto pose = clamped_lane_pose(map, *lane, s, lateral);
          EXPECT_TRUE(pose) << named.where << ": no pose at s = " << s;
          if (pose && pose->overshoot > 0) {
            // Files written for Apollo put a target a little past a lane's end, where Apollo
            // clamps. Ours never do.
            EXPECT_FALSE(file.string().starts_with(corpus_dir().string()))
                << named.where << ": s = " << s << " is beyond lane '" << position.lane << "'";
            overshoots_.insert(file.filename().string() + " " + named.where + ": '" +
                               position.lane + "' -> " + std::to_string(s) + " (length " +
                               std::to_string(map.lane(*lane).length()) + ")");
          }
          LanePosition here{*lane, s, lateral};
          // Vehicles drive from state to state along lanes; pedestrians walk where they like.
          if (previous && actor->kind != ActorKind::pedestrian) {
            EXPECT_TRUE(find_route(map, *previous, here))
                << named.where << ": no route from '" << map.lane(previous->lane).id << "' -> "
                << previous->s << " to '" << position.lane << "' -> " << s;
          }
          previous = here;
        }
      }
    }
    return lane_positions;
  }

  std::map<std::string, std::unique_ptr<RoadMap>> maps_;
  std::set<std::string> overshoots_;
  std::set<std::string> unavailable_maps_;
};

TEST_F(ScenarioLanes, SharedExamplesNameLanesOfTheirMaps) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  std::vector<fs::path> files = scenario_files(test::shared_dir() / "examples");
  ASSERT_FALSE(files.empty());
  int lane_positions = 0;
  for (const fs::path& file : files) lane_positions += check_file(file);
  EXPECT_GT(lane_positions, 50);  // the examples are mostly lane positions
  // Pinned: the targets the examples put past their lanes' ends (Apollo clamps them). A change
  // here means the map, the front end or the examples changed.
  for (const std::string& overshoot : overshoots_) std::cout << "clamped: " << overshoot << "\n";
  EXPECT_EQ(overshoots_.size(), 13u);
  // One example is written for CARLA's Town03, which is no Apollo map.
  EXPECT_EQ(unavailable_maps_, std::set<std::string>{"Town03"});
}

TEST_F(ScenarioLanes, SeedCorpusNamesLanesOfItsMaps) {
  SCENFUZZ_REQUIRE_SHARED_DIR();  // the san_francisco seeds
  std::vector<fs::path> files = scenario_files(corpus_dir() / "avunit");
  ASSERT_FALSE(files.empty());
  int lane_positions = 0;
  for (const fs::path& file : files) lane_positions += check_file(file);
  EXPECT_GT(lane_positions, 30);
  EXPECT_TRUE(unavailable_maps_.empty());
}

}  // namespace
}  // namespace scenfuzz
