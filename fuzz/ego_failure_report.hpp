// What `scenfuzz run` says about an ego plugin that failed (crashed, hung or returned an error):
// from Trace::ego_failure, or, for a simulation that did not fill it in, from the trace's end
// reason and its ego_failure event.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "physics/trace/trace.hpp"

namespace scenfuzz {

struct EgoFailureReport {
  std::optional<EgoFailure> failure;  // what the simulation recorded, when it did
  std::string message;                // the ego_failure event's message (the fallback)
  double time = 0;                    // simulated s at the failure
};

// The ego's failure in `trace`, or nullopt when it did not fail.
std::optional<EgoFailureReport> ego_failure_report(const Trace& trace);

// True when the plugin could not even be loaded or created: a bad --ego-plugin, not something
// the scenario found.
bool ego_failed_to_start(const Trace& trace, const EgoFailureReport& report);

// One line: "ego failure: ego_crash (SIGSEGV) at step 3, t = 0.1 s: <reason>".
std::string describe_ego_failure(const EgoFailureReport& report);

// {"kind", "reason", "signal", "step", "time", "last_observation"}; what is not known is null.
nlohmann::json ego_failure_json(const EgoFailureReport& report);

}  // namespace scenfuzz
