// The NPC vehicles' signals (npc_signals.hpp).
#include "physics/simulation/npc_signals.hpp"

#include <cmath>

namespace scenfuzz {

NpcSignals::NpcSignals(const RoadMap& map, const SimulationSetup& setup,
                       const std::vector<FlowVehicle>& flow_vehicles, const SignalWeather& weather,
                       const SignalSettings& settings)
    : setup_(&setup),
      settings_(settings),
      weather_(weather_signals(weather, settings)),
      actor_stretches_(setup.actors.size()),
      actor_cursors_(setup.actors.size()),
      moved_(setup.actors.size(), 0),
      vehicle_cursors_(flow_vehicles.size()) {
  for (std::size_t i = 0; i < setup.actors.size(); ++i) {
    const ScriptedActor& actor = setup.actors[i];
    if (actor.kind != TraceActorKind::vehicle || !actor.lane_drive) continue;
    const LaneRoute& route = actor.lane_drive->route;
    actor_stretches_[i] = route_indications(map, route.segments, lane_change_stretches(map, route));
  }
  for (const FlowPlan& flow : setup.flows)
    flow_stretches_.push_back(
        route_indications(map, flow.route.segments, lane_change_stretches(map, flow.route)));
  for (const FlowVehicle& vehicle : flow_vehicles) vehicle_flow_.push_back(vehicle.flow);
}

VehicleSignals NpcSignals::along_route(const std::vector<IndicationStretch>& stretches,
                                       IndicationCursor& cursor, double progress,
                                       double speed) const {
  if (stretches.empty()) return 0;
  return indicator_at(stretches, progress, speed, cursor, settings_.notice);
}

VehicleSignals NpcSignals::scenario_actor(std::size_t i, double t, const KinematicState& state,
                                          const LaneFollower* follower,
                                          const ManoeuvreDriver* driver) {
  const ScriptedActor& actor = setup_->actors[i];
  if (actor.kind != TraceActorKind::vehicle) return 0;
  // A scripted vehicle standing from the start is parked: no brake lights until it has moved.
  if (state.speed >= settings_.standing) moved_[i] = 1;
  const bool held = follower || driver || moved_[i];
  VehicleSignals signals =
      weather_ | brake_lights(state.acceleration, state.speed, held, settings_);
  if (driver) return signals | driver->indicator();
  if (actor_stretches_[i].empty()) return signals;  // most: nothing to indicate on the way
  const double progress = follower ? follower->progress() : actor.trajectory.distance_at(t);
  return signals | along_route(actor_stretches_[i], actor_cursors_[i], progress, state.speed);
}

VehicleSignals NpcSignals::flow_vehicle(std::size_t j, const KinematicState& state,
                                        const LaneFollower* follower) {
  if (!follower) return 0;  // not on the map
  const VehicleSignals signals =
      weather_ | brake_lights(state.acceleration, state.speed, true, settings_);
  return signals | along_route(flow_stretches_[vehicle_flow_[j]], vehicle_cursors_[j],
                               follower->progress(), state.speed);
}

}  // namespace scenfuzz
