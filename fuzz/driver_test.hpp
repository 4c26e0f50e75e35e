// An accident reconstruction as a test of the driver under test (AC3R, SoVAR): the written replay
// scenario run as `scenfuzz run` runs it, the driver in the ego's place and the other vehicles
// replaying the reconstruction heedless of it. The ego's first collision is judged for whose
// fault it was (oracle/responsibility.hpp) and, when it was the other's, for whether braking in
// time could have avoided it (oracle/collision_avoidability.hpp). docs/accident.md, "Testing a
// driver".
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "fuzz/scenario_evaluator.hpp"
#include "oracle/collision_avoidability.hpp"

namespace scenfuzz {

enum class DriverVerdict {
  avoided,      // the ego touched nobody
  unavoidable,  // hit through the other's fault, and braking could not have avoided it
  avoidable,    // hit through the other's fault, though braking in time would have avoided it
  caused,       // a collision the ego is to blame for, alone or in part
  ego_failure,  // the driver (a plugin) crashed, hung or returned an error while driving
};

// "avoided", "unavoidable", "avoidable", "caused", "ego_failure".
std::string_view driver_verdict_name(DriverVerdict verdict);

// Whether the verdict is a finding against the driver: avoidable, caused, ego_failure.
bool is_driver_finding(DriverVerdict verdict);

struct DriverTest {
  DriverVerdict verdict = DriverVerdict::avoided;
  ScenarioRun run;  // as `scenfuzz run` of the replay gives it, with the same options
  // The ego's first collision (an index into run.trace->collisions), whose fault it was and,
  // when the other's, whether it was avoidable.
  std::optional<std::size_t> collision;
  std::optional<CollisionResponsibility> responsibility;
  std::optional<Avoidability> avoidability;
  // Why the replay could not be run: infeasible, the simulation failed, or the ego plugin could
  // not be loaded or started. The verdict is then meaningless.
  std::string problem;
};

// Runs `replay` (a reconstruction's replay scenario, `file` the text it was printed to) with the
// driver `simulation` names, at seed 0 as `scenfuzz run` does. Throws MapError when the map
// cannot be loaded.
DriverTest test_driver(const SourceFile& file, const ScenarioTemplate& replay,
                       MapSearchPath search_path, const SimulationOptions& simulation,
                       const JudgeOptions& judge);

}  // namespace scenfuzz
