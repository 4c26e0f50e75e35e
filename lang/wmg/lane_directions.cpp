// Which way each lane of a junction's roads runs. WMG SDL numbers a road's lanes across the whole
// road ("Number of lanes [2] as [R1.L1, R1.L2]" is one lane each way, as level 1's defaults say)
// and says nothing of their direction but through the junction's `Road lane connections`: a lane
// a connection leaves from runs into the junction, a lane it leads to runs out of it. So a road's
// lanes become its arm's in and out lanes by those connections, and the map has as many lanes
// each way as the busiest arm needs (docs/wmg-semantics.md, "Lanes at a junction").
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "lang/wmg/scenario_translation.hpp"

namespace scenfuzz::wmg {
namespace {

enum class Direction { in, out };

struct LaneUse {
  Direction direction = Direction::in;
  SourceLocation location;  // where a connection first used it so
};

std::string written(const LaneName& lane) { return lane.road.name + "." + lane.lane.name; }

int lane_number(const std::string& name) {
  int number = 0;
  for (char c : name.substr(1)) number = number * 10 + (c - '0');
  return number;
}

// A lane both into and out of the junction is an error at the second use.
void use_lane(const LaneName& lane, Direction direction, const std::string& junction,
              std::map<std::string, LaneUse>& uses, Diagnostics& diagnostics) {
  if (!lane.lane.name.starts_with("L")) return;  // a pavement runs no way
  auto [use, added] = uses.try_emplace(written(lane), LaneUse{direction, lane.location});
  if (added || use->second.direction == direction) return;
  const bool into = use->second.direction == Direction::in;
  diagnostics.error(lane.location,
                    "lane '" + written(lane) + "' leads " + (into ? "out of" : "into") +
                        " junction '" + junction + "' here, but the connection at " +
                        std::to_string(use->second.location.line) + ":" +
                        std::to_string(use->second.location.column) + " leads it " +
                        (into ? "into" : "out of") +
                        " the junction: a lane runs one way (the lanes a connection leaves "
                        "from run into the junction, those it leads to run out of it)");
}

std::map<std::string, LaneUse> lane_uses(const Junction& junction, Diagnostics& diagnostics) {
  std::map<std::string, LaneUse> uses;
  for (const LaneConnection& connection : junction.lane_connections) {
    use_lane(connection.from, Direction::in, junction.id.name, uses, diagnostics);
    for (const LaneName& to : connection.to)
      use_lane(to, Direction::out, junction.id.name, uses, diagnostics);
  }
  return uses;
}

// The road's traffic lanes in number order (L1 first: the kerb side of each direction).
std::vector<const LaneName*> traffic_lanes(const Road& road) {
  std::vector<const LaneName*> lanes;
  for (const LaneName& lane : road.lanes)
    if (lane.lane.name.starts_with("L")) lanes.push_back(&lane);
  std::stable_sort(lanes.begin(), lanes.end(), [](const LaneName* a, const LaneName* b) {
    return lane_number(a->lane.name) < lane_number(b->lane.name);
  });
  return lanes;
}

// Names the road's lanes on `arm`; returns the lanes each way the arm needs. A lane no connection
// names runs the way fewer of its road's lanes run (those the connections name, then the unnamed
// ones before it), into the junction on a tie, so that an unnamed two-lane road is one lane each
// way too.
int name_arm_lanes(const Road& road, const std::string& arm,
                   const std::map<std::string, LaneUse>& uses, RoadLanes& lanes) {
  const std::vector<const LaneName*> road_lanes = traffic_lanes(road);
  std::vector<Direction> directions;
  int in = 0, out = 0;
  for (const LaneName* lane : road_lanes) {
    auto use = uses.find(written(*lane));
    if (use == uses.end()) continue;
    ++(use->second.direction == Direction::in ? in : out);
  }
  for (const LaneName* lane : road_lanes) {
    auto use = uses.find(written(*lane));
    if (use != uses.end()) {
      directions.push_back(use->second.direction);
      continue;
    }
    directions.push_back(in <= out ? Direction::in : Direction::out);
    ++(directions.back() == Direction::in ? in : out);
  }
  int next_in = 0, next_out = 0;
  for (std::size_t i = 0; i < road_lanes.size(); ++i) {
    const bool into = directions[i] == Direction::in;
    lanes.ids[written(*road_lanes[i])] =
        arm + (into ? "_in_" : "_out_") + std::to_string(into ? next_in++ : next_out++);
  }
  return std::max(in, out);
}

}  // namespace

int name_junction_lanes(const Junction& junction, const std::vector<const Road*>& roads,
                        const std::vector<std::string>& arms, Translation& translation) {
  const std::map<std::string, LaneUse> uses = lane_uses(junction, translation.diagnostics);
  int lanes_each_way = 1;
  for (std::size_t i = 0; i < roads.size() && i < arms.size(); ++i) {
    if (!roads[i]) continue;
    RoadLanes& lanes = translation.roads[roads[i]->id.name];
    lanes_each_way = std::max(lanes_each_way, name_arm_lanes(*roads[i], arms[i], uses, lanes));
  }
  for (std::size_t i = 0; i < roads.size(); ++i)
    if (roads[i]) translation.roads[roads[i]->id.name].traffic_lanes = lanes_each_way;
  return lanes_each_way;
}

}  // namespace scenfuzz::wmg
