// A campaign round under mpirun: rank 0 (which owns the database and the schedule) hands the
// round's searches to the other ranks through the MPI pool (mpi_pool.hpp) and records their
// results in the round's order as they arrive (RoundRecorder), so the database ends as with one
// process. The other ranks load the same seeds and serve searches until rank 0 releases them.
#pragma once

#include <cstdint>
#include <vector>

#include "fuzz/campaign/campaign_round.hpp"
#include "fuzz/campaign/mpi_pool.hpp"

namespace scenfuzz {

// Rank 0: runs `tasks` on the worker ranks (context.mpi) and records them.
RoundEnd run_round_on_ranks(RoundContext& context, std::int64_t round,
                            std::vector<CampaignSearchTask> tasks);

// Any other rank: runs the searches rank 0 sends, each with `threads` evaluations at once (0:
// all cores), until released. SIGINT and SIGTERM (mpirun passes them on) stop the search in
// flight after its batch; what it did goes back to rank 0.
void serve_campaign_searches(MpiSession& mpi, const CampaignSeeds& seeds,
                             const SimulationCommandOptions& simulation, std::size_t threads);

}  // namespace scenfuzz
