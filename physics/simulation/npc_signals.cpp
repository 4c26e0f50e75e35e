// The NPC vehicles' signals (npc_signals.hpp).
#include "physics/simulation/npc_signals.hpp"

#include <algorithm>
#include <cmath>

#include "physics/simulation/lane_tracker.hpp"
#include "physics/simulation/path_indications.hpp"

namespace scenfuzz {

NpcSignals::NpcSignals(const RoadMap& map, const SimulationSetup& setup,
                       const std::vector<std::optional<LaneFollower>>& followers,
                       const std::vector<FlowVehicle>& flow_vehicles, const SignalWeather& weather,
                       const SignalSettings& settings)
    : setup_(&setup),
      settings_(settings),
      lights_(weather_signals(weather, settings)),
      slots_(setup.actors.size()),
      actor_stretches_(setup.actors.size()),
      actor_cursors_(setup.actors.size()),
      vehicle_cursors_(flow_vehicles.size()) {
  for (std::size_t i = 0; i < setup.actors.size(); ++i) {
    const ScriptedActor& actor = setup.actors[i];
    Slot& slot = slots_[i];
    slot.vehicle = actor.kind == TraceActorKind::vehicle;
    if (!slot.vehicle) continue;
    if (actor.lane_drive) {
      const LaneRoute& route = actor.lane_drive->route;
      actor_stretches_[i] =
          route_indications(map, route.segments, lane_change_stretches(map, route));
    } else if (!actor.manoeuvres) {
      // Its path through its waypoints (or standing: none), read off the map.
      actor_stretches_[i] = path_indications(map, actor.trajectory.path(), map.widest_half_lane());
    }
    slot.indicates = actor.manoeuvres || !actor_stretches_[i].empty();
    if (slot.indicates) indicating_.push_back(i);
    // A scripted vehicle standing from the start is parked: no brake lights until it moves.
    slot.driven = actor.manoeuvres.has_value() || followers[i].has_value();
  }
  for (const FlowPlan& flow : setup.flows)
    flow_stretches_.push_back(
        route_indications(map, flow.route.segments, lane_change_stretches(map, flow.route)));
  for (const FlowVehicle& vehicle : flow_vehicles) vehicle_flow_.push_back(vehicle.flow);
}

VehicleSignals NpcSignals::actor_indicator(std::size_t i, double t, const KinematicState& state,
                                           const LaneFollower* follower,
                                           const ManoeuvreDriver* driver) {
  if (driver) return driver->indicator();
  if (actor_stretches_[i].empty()) return 0;
  const double progress =
      follower ? follower->progress() : setup_->actors[i].trajectory.distance_at(t);
  return indicator_at(actor_stretches_[i], progress, state.speed, actor_cursors_[i],
                      settings_.notice);
}

VehicleSignals NpcSignals::flow_indicator(std::size_t j, const KinematicState& state,
                                          const LaneFollower& follower) {
  const auto& stretches = flow_stretches_[vehicle_flow_[j]];
  if (stretches.empty()) return 0;
  return indicator_at(stretches, follower.progress(), state.speed, vehicle_cursors_[j],
                      settings_.notice);
}

void NpcSignals::record(double t, std::span<const KinematicState> states,
                        const std::vector<std::optional<LaneFollower>>& followers,
                        const std::vector<std::optional<ManoeuvreDriver>>& drivers,
                        const BackgroundTraffic& traffic, std::size_t first_flow,
                        std::vector<WorldObject>* truth) {
  if (indicators_.empty()) indicators_.assign(states.size(), 0);
  for (const std::size_t i : indicating_)
    note(i + 1, actor_indicator(i, t, states[i + 1], followers[i] ? &*followers[i] : nullptr,
                                drivers[i] ? &*drivers[i] : nullptr));
  for (std::size_t j = 0; j < traffic.size(); ++j) {
    const LaneFollower* follower = traffic.follower(j);
    const std::size_t k = first_flow + j;
    if (follower)
      note(k, flow_indicator(j, states[k], *follower));
    else if (indicators_[k] != 0)
      note(k, 0);  // it left the map
  }
  if (truth) set_truth(states, traffic, first_flow, *truth);
  ++sample_;
}

void NpcSignals::set_truth(std::span<const KinematicState> states, const BackgroundTraffic& traffic,
                           std::size_t first_flow, std::vector<WorldObject>& truth) {
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    Slot& slot = slots_[i];
    if (!slot.vehicle) continue;
    const KinematicState& state = states[i + 1];
    slot.moved = slot.moved || state.speed >= settings_.standing;
    truth[i].signals = lights_ | indicators_[i + 1] |
                       brake(state.acceleration, state.speed, slot.driven || slot.moved);
  }
  for (std::size_t j = 0; j < traffic.size(); ++j) {
    const std::size_t k = first_flow + j;
    truth[k - 1].signals =
        traffic.follower(j) == nullptr
            ? VehicleSignals{0}
            : static_cast<VehicleSignals>(lights_ | indicators_[k] |
                                          brake(states[k].acceleration, states[k].speed, true));
  }
}

void NpcSignals::complete(TraceActor& actor, bool driven, std::size_t from,
                          std::size_t until) const {
  const std::size_t n = actor.x.size();
  bool moved = driven;
  for (std::size_t i = from; i < std::min(until, n); ++i) {
    moved = moved || actor.speed[i] >= settings_.standing;
    actor.signals[i] = static_cast<VehicleSignals>(
        actor.signals[i] | lights_ | brake(actor.acceleration[i], actor.speed[i], moved));
  }
}

void NpcSignals::finish(std::vector<TraceActor>& actors, std::size_t first_flow) const {
  for (std::size_t i = 0; i < slots_.size(); ++i)
    if (slots_[i].vehicle) actors[i + 1].signals.assign(actors[i + 1].x.size(), 0);
  for (std::size_t k = first_flow; k < actors.size(); ++k)
    actors[k].signals.assign(actors[k].x.size(), 0);
  // Each change holds until the actor's next one (changes_ is in sample order).
  for (const Change& change : changes_) {
    std::vector<VehicleSignals>& column = actors[change.actor].signals;
    std::fill(column.begin() + static_cast<std::ptrdiff_t>(std::min(change.sample, column.size())),
              column.end(), change.indicator);
  }
  for (std::size_t i = 0; i < slots_.size(); ++i)
    if (slots_[i].vehicle) complete(actors[i + 1], slots_[i].driven, 0, actors[i + 1].x.size());
  for (std::size_t k = first_flow; k < actors.size(); ++k)
    complete(actors[k], true, actors[k].present_from, actors[k].present_until);
}

}  // namespace scenfuzz
