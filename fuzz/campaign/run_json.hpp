// A campaign run's summary for scripts (`campaign run --json`): the run, its simulations, the
// exit status and why, and the failure modes grouped by their status in this run, with their
// fields and replay tallies. docs/campaigns.md, "Regression replay and CI outputs", shows one.
#pragma once

#include <nlohmann/json.hpp>

#include "fuzz/campaign/run_summary.hpp"

namespace scenfuzz {

// Groups "new", "still_failing", "fixed", "flaky" and "regressed" hold the modes whose status
// is this run's verdict (found by a search, or replayed); "replay_errors" those whose replay met
// an error and "not_replayed" those this run learnt nothing about (both keep an older status).
// Every group is present, empty or not.
nlohmann::json run_json(const RunSummary& summary);

}  // namespace scenfuzz
