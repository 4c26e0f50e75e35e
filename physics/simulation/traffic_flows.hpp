// Background traffic (a scenario's Flow items, Traffic::flows): each flow's lanes, route and path
// resolved when the scenario is set up, and the vehicles it sends drawn once per run from a
// generator seeded by (run seed, flow index): the road pre-filled at t = 0 at the flow's density
// (rate / speed), then arrivals at the route's start as a Poisson process at its rate. The
// simulation lets each arrival in once its entry is clear (spillback) and drives every one by a
// LaneFollower that leaves the map at its route's end (docs/simulation.md, "Background traffic").
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "physics/actors/actor_class.hpp"
#include "physics/actors/kinematics.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/scenario_setup.hpp"

namespace scenfuzz {

// The most flow vehicles one run has, over all flows: beyond it a city's worth of flows for an
// hour would cost more memory and time than the search can give one evaluation.
inline constexpr std::size_t kMaxFlowVehicles = 500;

// One vehicle a flow sends.
struct FlowVehicle {
  std::size_t flow = 0;  // index into SimulationSetup::flows
  std::string name;      // "<flow name>.<n>", n from 1
  double due = 0;        // s: when it arrives at the route's start (0 when pre-filled)
  double progress = 0;   // m along the flow's path where a pre-filled one stands at t = 0
  bool prefilled = false;
};

struct FlowSchedule {
  std::vector<FlowVehicle> vehicles;  // by flow, then n
  std::vector<std::size_t> capped;    // flows that lost vehicles to kMaxFlowVehicles
};

// What every flow vehicle is, on a dry road (FlowPlan::body is it on the scenario's road).
ActorClass flow_vehicle_body();

// Resolves the scenario's flows into setup.flows. An unknown lane, no route to the destination
// lane, or a rate or speed that is not a usable number is an error at the flow's place in the
// file; a flow whose vehicles over the scenario's duration pass kMaxFlowVehicles gets a warning
// naming it. setup's actors and obstacles must be prepared (the pre-fill keeps clear of them).
void prepare_flows(const ScenarioTemplate& scenario, std::span<const double> values,
                   const RoadMap& map, std::uint64_t seed, SimulationSetup& setup,
                   Diagnostics& diagnostics);

// Every vehicle setup's flows send in a run of `duration` seconds: the same for the same setup
// (its flows' seeds), and a longer run's schedule extends a shorter one's. Pre-filled vehicles
// that would stand within the safe gap of an actor's or obstacle's initial pose, or of another
// pre-filled vehicle, are left out.
FlowSchedule draw_flow_schedule(const SimulationSetup& setup, double duration);

// The speed a vehicle of `flow` enters the start of its route at now, or nullopt while the entry
// is taken. Given the present bodies (by actor id: state, length, width, present flag), it
// enters at the flow's speed, or at the speed of the slowest body in line ahead of the entry
// within the distance it needs to brake to it comfortably (no arrival at full speed into a
// queue); the entry is taken while any body stands within the safe gap at that speed, ahead or
// behind, or near enough to touch.
std::optional<double> flow_entry_speed(const FlowPlan& flow, std::span<const KinematicState> states,
                                       std::span<const double> lengths,
                                       std::span<const double> widths,
                                       std::span<const std::uint8_t> present);

}  // namespace scenfuzz
