// A campaign run's summary for the tests of its CI outputs (JUnit XML, --json, exit status):
// run 3 of campaign "nightly", with one failure mode per way a run can leave one.
#pragma once

#include <string>

#include "fuzz/campaign/run_summary.hpp"

namespace scenfuzz::test {

// A mode of seed `seed` with status `status`, first and last seen in the given runs.
inline RunFailureMode sample_mode(std::int64_t id, const std::string& seed,
                                  FailureModeStatus status, std::int64_t first_seen,
                                  std::int64_t last_seen) {
  RunFailureMode entry;
  entry.mode.id = id;
  entry.mode.record.seed_id = seed == "corpora/avunit/cut_in_straight.avu" ? 1 : 2;
  entry.mode.record.signature =
      "collision | car cutter | ego | cruising | straight | rear-front #" + std::to_string(id);
  entry.mode.record.spec = "no_collision";
  entry.mode.record.responsibility = "ego";
  entry.mode.record.scenario_file = "modes/00000000000000" + std::to_string(10 + id) + ".avu";
  entry.mode.record.replay_command =
      "scenfuzz run --map-path maps " + entry.mode.record.scenario_file;
  entry.mode.first_seen_run = first_seen;
  entry.mode.last_seen_run = last_seen;
  entry.mode.status = status;
  entry.seed_path = seed;
  return entry;
}

inline RunSummary empty_run() {
  RunSummary summary;
  summary.campaign = "nightly";
  summary.run = {3, "2026-11-27T02:00:00Z", "2026-11-27T03:00:00Z", "3f2c9e1"};
  summary.simulations = 2000;
  return summary;
}

}  // namespace scenfuzz::test
