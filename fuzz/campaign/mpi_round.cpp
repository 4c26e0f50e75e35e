// run_round_on_ranks and serve_campaign_searches: the two ends of a round under mpirun.
#include "fuzz/campaign/mpi_round.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <map>
#include <thread>

#include "fuzz/campaign/search_wire.hpp"
#include "fuzz/stop_signals.hpp"
#include "lang/demand.hpp"

namespace scenfuzz {

namespace {

using Clock = std::chrono::steady_clock;

// The search of one task on a worker rank, as bytes for rank 0; never throws (an exception
// would end the rank, and rank 0 would hand the same search to the next one).
std::string run_task(const CampaignSeeds& seeds, const SimulationCommandOptions& simulation,
                     std::size_t threads, const std::string& payload,
                     const std::function<bool()>& stop) {
  CampaignSearchResult result;
  std::vector<WireFile> files;
  try {
    CampaignSearchTask task = decode_task(payload);
    task.threads = threads;
    SCENFUZZ_DEMAND(task.arm < seeds.arms.size());
    result = run_campaign_search(seeds, simulation, task, stop);
    std::string error;
    if (result.error.empty()) files = finding_files(result, error);
    if (!error.empty()) result.error = "scenfuzz: error: " + error + "\n";
  } catch (const std::exception& error) {
    result.error = std::string("scenfuzz: error: ") + error.what() + "\n";
  }
  return encode_result(result, files);
}

// What rank 0 makes of a worker's bytes: the result, with its files placed on this disk.
RoundSlot receive(const std::string& bytes) {
  RoundSlot slot;
  std::vector<WireFile> files;
  slot.result = decode_result(bytes, files);
  if (slot.result.error.empty())
    if (std::string error = place_files(files); !error.empty())
      slot.result.error = "scenfuzz: error: " + error + "\n";
  return slot;
}

}  // namespace

RoundEnd run_round_on_ranks(RoundContext& context, std::int64_t round,
                            std::vector<CampaignSearchTask> tasks) {
  SCENFUZZ_DEMAND(context.mpi != nullptr);
  // The wall time left when the round starts: tasks are sent as they are.
  if (context.deadline)
    for (CampaignSearchTask& task : tasks)
      task.time_limit =
          std::max(1e-3, std::chrono::duration<double>(*context.deadline - Clock::now()).count());
  // The largest searches first, so that the round does not wait on a large one handed out last.
  std::vector<MpiTask> sent;
  for (std::size_t i = 0; i < tasks.size(); ++i)
    sent.push_back({static_cast<std::int64_t>(i), encode_task(tasks[i])});
  std::stable_sort(sent.begin(), sent.end(), [&](const MpiTask& a, const MpiTask& b) {
    return tasks[static_cast<std::size_t>(a.id)].budget >
           tasks[static_cast<std::size_t>(b.id)].budget;
  });
  RoundRecorder recorder(context, round);
  std::map<std::size_t, RoundSlot> arrived;  // results waiting for an earlier one
  std::size_t next = 0;
  const auto on_result = [&](std::int64_t id, const std::string& bytes) {
    arrived[static_cast<std::size_t>(id)] = receive(bytes);
    for (auto slot = arrived.find(next); slot != arrived.end(); slot = arrived.find(next)) {
      recorder.take(tasks[next++], slot->second);
      arrived.erase(slot);
    }
  };
  const auto stop = [&] {
    return StopSignalGuard::stop_requested() || recorder.failed() ||
           (context.deadline && Clock::now() >= *context.deadline);
  };
  context.mpi->distribute(sent, on_result, stop, context.mpi_times);
  if (context.mpi->live_workers() == 0) {
    context.err << "scenfuzz: error: every MPI worker rank has died; the run stops (run it again "
                   "to continue)\n";
    return RoundEnd::failed;
  }
  // Tasks never handed out (a stop, the wall time) close the round in order.
  for (; next < tasks.size(); ++next) {
    auto slot = arrived.find(next);
    recorder.take(tasks[next], slot != arrived.end() ? slot->second : RoundSlot{true, {}});
  }
  return recorder.end();
}

void serve_campaign_searches(MpiSession& mpi, const CampaignSeeds& seeds,
                             const SimulationCommandOptions& simulation, std::size_t threads) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  StopSignalGuard guard;
  mpi.serve(
      [&](const std::string& payload, const std::function<bool()>& stop) {
        return run_task(seeds, simulation, threads, payload, stop);
      },
      [] { return StopSignalGuard::stop_requested(); });
}

}  // namespace scenfuzz
