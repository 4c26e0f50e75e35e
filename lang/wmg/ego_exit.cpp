// Where the ego leaves a junction. WMG SDL gives the ego (`DO: AUTO`) no destination, but the
// scenery's `Road lane connections [R3.L1 -> R1.L2 + R2.L1, ...]` say where each lane leads.
// Without a destination the ego would take the lanes ahead (straight on, or the gentler turn),
// which need not be a way the file allows; so it takes the first connection written from its
// lane, to kExitDistance metres along that road (docs/wmg-semantics.md, "Actors").
#include <string>

#include "lang/wmg/scenario_translation.hpp"

namespace scenfuzz::wmg {
namespace {

// Far enough along the road it turns into that the ego has left the junction and straightened.
constexpr double kExitDistance = 20;

// The lane the ego is initialised in, as written.
const LaneName* ego_lane(const Initialisation& initialisation, const std::string& ego) {
  if (initialisation.first.actor.name == ego) return &initialisation.first.lane;
  for (const RelativeActorInit& init : initialisation.relative)
    if (init.actor.name == ego) return &init.lane;
  return nullptr;
}

const LaneConnection* connection_from(const Junction& junction, const LaneName& lane) {
  for (const LaneConnection& connection : junction.lane_connections)
    if (connection.from.road.name == lane.road.name &&
        connection.from.lane.name == lane.lane.name && !connection.to.empty())
      return &connection;
  return nullptr;
}

}  // namespace

void choose_ego_exit(const Scenery& scenery, const Dynamics& dynamics, Translation& translation) {
  if (scenery.junctions.empty()) return;
  const LaneName* lane = ego_lane(dynamics.initialisation, ego_name(dynamics));
  if (!lane) return;
  const LaneConnection* connection = connection_from(scenery.junctions.front(), *lane);
  if (!connection) return;
  const LaneName& exit = connection->to.front();
  // A lane a connection leads to is an out lane (lane_directions.cpp); where the map names it as
  // an in lane all the same (a pavement), the ego leaves by the out lane of that number.
  std::string id = translation.lane_id(exit).value_or("");
  if (id.empty()) return;
  if (const std::string::size_type in = id.rfind("_in_"); in != std::string::npos)
    id.replace(in, 4, "_out_");
  State target;
  target.position.kind = PositionKind::lane;
  target.position.lane = id;
  target.position.s = constant_value(kExitDistance, exit.location);
  target.position.location = exit.location;
  target.location = exit.location;
  translation.scenario.ego.target = target;
}

}  // namespace scenfuzz::wmg
