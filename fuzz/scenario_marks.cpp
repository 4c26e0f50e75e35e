// Marks for a scenario's map picture: actors from the simulation's own setup (so the picture
// shows what a run starts with, not a second reading of the file), roads from the notes the WMG
// translation keeps on the map ("road R3" -> "the south arm (R3.L1 south_in_0, ...)").
#include "fuzz/scenario_marks.hpp"

#include "physics/simulation/scenario_setup.hpp"

namespace scenfuzz {
namespace {

// The lane-id prefixes in a road note's parentheses: "(south_in_*, south_out_*)", or the lanes
// it names where the junction's connections said which way each runs: "(R3.L1 south_in_0, ...)".
std::vector<std::string> lane_prefixes(const std::string& note) {
  std::vector<std::string> prefixes;
  const std::size_t open = note.find('(');
  const std::size_t close = note.find(')', open);
  if (open == std::string::npos || close == std::string::npos) return prefixes;
  std::string list = note.substr(open + 1, close - open - 1);
  std::size_t start = 0;
  while (start < list.size()) {
    std::size_t end = list.find(',', start);
    if (end == std::string::npos) end = list.size();
    std::string item = list.substr(start, end - start);
    item = item.substr(item.rfind(' ') + 1);  // the map's lane id, after a written lane name
    if (item.ends_with('*')) item.pop_back();
    if (!item.empty()) prefixes.push_back(item);
    start = end + 1;
  }
  return prefixes;
}

// The middle of the road's lanes outside junctions: the centre of its carriageway half-way along.
std::optional<MapPoint> road_middle(const RoadMap& map, const std::vector<std::string>& prefixes) {
  MapPoint sum{0, 0};
  int lanes = 0;
  for (const Lane& lane : map.lanes()) {
    if (lane.junction) continue;
    for (const std::string& prefix : prefixes)
      if (lane.id.starts_with(prefix)) {
        const MapPoint middle = lane.centre_line.point_at(lane.length() / 2);
        sum = {sum.x + middle.x, sum.y + middle.y};
        ++lanes;
        break;
      }
  }
  if (lanes == 0) return std::nullopt;
  return MapPoint{sum.x / lanes, sum.y / lanes};
}

void add_road_marks(const ScenarioTemplate& scenario, const RoadMap& map,
                    std::vector<SvgMark>& marks) {
  for (const Attribute& note : scenario.map.attributes) {
    if (!note.key.starts_with("road ")) continue;
    if (const auto middle = road_middle(map, lane_prefixes(note.value)))
      marks.push_back(SvgMark{MapPose{*middle, 0}, 0, 0, note.key.substr(5)});
  }
}

// "Car (FSL of Ego)" for an actor placed relative to another, else its name.
std::string actor_text(const Actor& actor) {
  const Position& position = actor.initial.position;
  if (position.kind != PositionKind::relative || position.relative_location.empty())
    return actor.name;
  return actor.name + " (" + position.relative_location + " of " + position.reference + ")";
}

const Actor* actor_named(const ScenarioTemplate& scenario, const std::string& name) {
  for (const std::vector<Actor>* actors : {&scenario.vehicles, &scenario.pedestrians})
    for (const Actor& actor : *actors)
      if (actor.name == name) return &actor;
  return nullptr;
}

void add_actor_marks(const ScenarioTemplate& scenario, const SimulationSetup& setup,
                     std::vector<SvgMark>& marks) {
  const KinematicState& ego = setup.ego_initial;
  marks.push_back(SvgMark{MapPose{{ego.x, ego.y}, ego.heading}, setup.ego_body.length,
                          setup.ego_body.width, scenario.ego.name + " (ego)"});
  if (setup.ego_target)
    marks.push_back(SvgMark{*setup.ego_target, 0, 0, scenario.ego.name + "'s target"});
  for (const ScriptedActor& actor : setup.actors) {
    const KinematicState start = actor.trajectory.state_at(0);
    const Actor* written = actor_named(scenario, actor.name);
    marks.push_back(SvgMark{MapPose{{start.x, start.y}, start.heading}, actor.body.length,
                            actor.body.width, written ? actor_text(*written) : actor.name});
  }
}

}  // namespace

std::vector<SvgMark> scenario_marks(const ScenarioTemplate& scenario,
                                    std::span<const double> values, const RoadMap& map,
                                    Diagnostics& diagnostics) {
  std::vector<SvgMark> marks;
  add_road_marks(scenario, map, marks);
  if (const auto setup = prepare_simulation(scenario, values, map, 1, diagnostics))
    add_actor_marks(scenario, *setup, marks);
  return marks;
}

}  // namespace scenfuzz
