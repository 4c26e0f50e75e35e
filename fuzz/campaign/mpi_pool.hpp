// A campaign's searches spread over the ranks of an MPI job (`mpirun -np N scenfuzz campaign run
// DIR`): rank 0 owns the database and the schedule and hands out tasks; every other rank runs
// them and sends back results. Tasks and results are opaque byte strings here, so this file (the
// only one including mpi.h) knows nothing of searches.
//
// A worker that dies (kill -9, a lost machine) only loses the task it was running: workers send
// a heartbeat every `heartbeat_seconds` while they work, and rank 0 hands the task of a worker
// silent for `dead_after_seconds` to another. Open MPI aborts the whole job when a rank dies
// unless mpirun is given `--enable-recovery` (docs/campaigns.md); a job aborted that way is
// continued by the next `campaign run`, like any killed run.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace scenfuzz {

// Whether this process was started by mpirun (Open MPI's or PMIx's environment): only then is
// MPI initialised, so a plain `scenfuzz campaign run` never touches MPI.
bool launched_by_mpirun();

struct MpiTask {
  std::int64_t id = 0;  // the caller's; results come back under it
  std::string payload;
};

struct MpiPoolTimes {
  double heartbeat_seconds = 1;
  double dead_after_seconds = 30;
};

// A worker's job: the result for a task's payload. `interrupted` says when the job should stop
// early (the process was asked to stop); the job returns what it has then.
using MpiJob = std::function<std::string(const std::string& payload,
                                         const std::function<bool()>& interrupted)>;

// The MPI job of this process, from MPI_Init to MPI_Finalize (the object's lifetime). One per
// process. Throws std::runtime_error when MPI cannot start.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  // Rank 0: runs `tasks` on the live workers, calling `on_result` (on this thread) for each
  // result as it arrives. Returns the ids of the tasks not done: all of them once every worker
  // is dead, those not yet handed out once `interrupted` says so (tasks in flight are waited
  // for: their workers stop them early and send what they have).
  std::vector<std::int64_t> distribute(
      const std::vector<MpiTask>& tasks,
      const std::function<void(std::int64_t id, const std::string& result)>& on_result,
      const std::function<bool()>& interrupted, const MpiPoolTimes& times = {});

  // Rank 0, at the end: tells every live worker to return from serve(). The destructor does it
  // when nobody did (rank 0 stopped at an error), so that no worker waits forever.
  void release_workers();

  // Any other rank: runs the tasks rank 0 sends with `job` until released. `interrupted` is
  // polled while a job runs and passed to it.
  void serve(const MpiJob& job, const std::function<bool()>& interrupted,
             const MpiPoolTimes& times = {});

  // Workers rank 0 has not declared dead.
  int live_workers() const;

 private:
  int rank_ = 0;
  int size_ = 1;
  std::vector<bool> dead_;  // by rank
  bool released_ = false;
};

}  // namespace scenfuzz
