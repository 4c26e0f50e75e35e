// The simulation loop: a prepared scenario stepped at a fixed dt into a Trace. Scripted actors
// follow their trajectories, the ego is driven by the reference driver (or a plugin in a child
// process) through its perception, unless it replays a script (an accident reconstruction), the
// collision world is checked every step, and the run ends at the duration, when the ego reaches
// its target, or at its first collision.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "physics/ego/perception.hpp"
#include "physics/ego/reference_driver.hpp"
#include "physics/simulation/scenario_setup.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

struct SimulationOptions {
  double dt = 0.05;                // s per step
  std::optional<double> duration;  // overrides the scenario's
  bool stop_at_collision = true;   // end at the first collision involving the ego
  // At an impact between scenario vehicles (the ego included) or with an obstacle, they stop
  // following their scripts and slide (impact_slide.hpp): an accident's chain of collisions.
  // Otherwise bodies pass through each other after their first contact.
  bool slide_after_impact = false;
  std::uint64_t seed = 0;         // perception noise and misses; passed to a plugin
  PerceptionSettings perception;  // clear-weather figures, degraded by the scenario's weather
  DriverSettings driver;
  std::string ego_plugin;          // a shared library to drive the ego; empty: the reference driver
  double plugin_step_timeout = 2;  // s of wall time a plugin may take for one step
  double plugin_start_timeout = 10;  // s of wall time for loading a plugin and its create
  double target_reach = 2;           // m: the ego has reached its target within this distance
  // How lane-following NPCs drive, over what the scenario says (unset: as it says).
  std::optional<NpcBehaviour> npc_behaviour;
};

// Throws std::invalid_argument when the duration and dt take more samples than a trace may hold
// (sample_count_problem in simulation_limits.hpp says so beforehand).
Trace simulate(const RoadMap& map, const SimulationSetup& setup, const SimulationOptions& options);

}  // namespace scenfuzz
