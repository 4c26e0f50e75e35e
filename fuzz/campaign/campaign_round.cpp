// run_round: a pool of worker threads runs a round's searches; the calling thread records their
// results one by one in the round's order as they become available.
#include "fuzz/campaign/campaign_round.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <numeric>
#include <set>
#include <thread>
#include <utility>

#include "fuzz/campaign/mode_files.hpp"
#include "fuzz/campaign/mpi_round.hpp"
#include "fuzz/findings_tmin.hpp"
#include "fuzz/stop_signals.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz {

namespace {

using Clock = std::chrono::steady_clock;

std::string quoted(const std::string& text) {
  if (text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                             "_-./=:+,") == std::string::npos &&
      !text.empty())
    return text;
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// What a worker hands the recorder.
struct Slot : RoundSlot {
  bool ready = false;
};

// The results of a round's tasks, filled by the workers, read in order by the recorder.
class RoundResults {
 public:
  explicit RoundResults(std::size_t count) : slots_(count) {}

  void put(std::size_t index, Slot slot) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      slots_[index] = std::move(slot);
      slots_[index].ready = true;
    }
    changed_.notify_all();
  }

  Slot take(std::size_t index) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return slots_[index].ready; });
    return std::move(slots_[index]);
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<Slot> slots_;
};

SearchRecord search_record(const RoundContext& context, std::int64_t round,
                           const CampaignSearchTask& task, const CampaignSearchResult& result) {
  const CampaignArm& arm = context.seeds.arms[task.arm];
  const LoadedSeed& seed = context.seeds.seeds[arm.seed];
  SearchRecord record;
  record.run_id = context.run;
  record.seed_id = seed.id;
  record.algorithm = seed.algorithm;
  record.budget = task.budget;
  record.status =
      result.summary.stop == StopReason::time_limit ? SearchStatus::stopped : SearchStatus::done;
  record.output_folder = task.folder;
  record.round = round;
  record.spec_index = static_cast<std::int64_t>(arm.spec);
  record.spec = arm.spec_name;
  record.search_seed = task.seed;
  record.simulations = result.summary.judged + result.summary.failed;
  record.best_robustness = result.best;
  return record;
}

// [search] tmin: the representatives of `modes` new to their seed minimised beside them in
// DIR/modes/, before the search is recorded (so a killed run, continued, finds the search to
// record again and what was minimised in place). One that cannot be minimised is warned of.
// False when a stop came first: the search is then left to be recorded by the continued run.
bool minimise_new_modes(RoundContext& context, const std::vector<FailureModeRecord>& modes) {
  std::set<std::pair<std::int64_t, std::string>> known;
  for (const CampaignFailureMode& mode : context.db.list_failure_modes())
    known.emplace(mode.record.seed_id, mode.record.signature);
  std::vector<TminJob> jobs;
  for (const FailureModeRecord& mode : modes)
    if (!known.contains({mode.seed_id, mode.signature}))
      jobs.push_back({mode.scenario_file, minimised_mode_file(mode.scenario_file)});
  const std::vector<TminJobResult> results =
      minimise_findings(jobs, context.workers, [] { return StopSignalGuard::stop_requested(); });
  bool stopped = false;
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    stopped = stopped || results[k].interrupted;
    if (results[k].minimised_file.empty() && !results[k].interrupted)
      context.err << "scenfuzz: warning: the failure mode of " << jobs[k].finding_file
                  << " is not minimised: " << results[k].reason << "\n";
  }
  return !stopped;
}

// Copies the modes' files into DIR/modes/, minimises the new ones ([search] tmin) and records
// the search with them; `failed` after an error on `err`, `interrupted` when a stop came during
// the minimisation.
RoundEnd record(RoundContext& context, std::int64_t round, const CampaignSearchTask& task,
                const CampaignSearchResult& result) {
  const CampaignArm& arm = context.seeds.arms[task.arm];
  const LoadedSeed& seed = context.seeds.seeds[arm.seed];
  std::vector<FailureModeRecord> modes;
  for (const FoundMode& found : result.modes) {
    const ModeFiles files = copy_mode_files(".", found.finding_file);
    if (!files.error.empty()) {
      context.err << "scenfuzz: error: " << files.error << "\n";
      return RoundEnd::failed;
    }
    modes.push_back(
        {seed.id, found.signature, found.spec, found.responsibility, files.scenario_file,
         replay_command(context.simulation, files.scenario_file, found.seed, seed.scenario)});
  }
  if (context.tmin && !minimise_new_modes(context, modes)) return RoundEnd::interrupted;
  const SearchRecord search = search_record(context, round, task, result);
  const RecordedSearch recorded =
      context.db.record_search_result(search, result.evaluations, modes, result.coverage);
  context.out << "round " << round << ": " << seed.path << " " << arm.spec_name << ": "
              << search.simulations << " simulations";
  if (result.best) context.out << ", best " << format_number(*result.best);
  context.out << ", " << modes.size() << (modes.size() == 1 ? " failure mode" : " failure modes")
              << " (" << recorded.new_modes << " new)";
  if (search.status == SearchStatus::stopped) context.out << ", stopped at the wall time";
  context.out << "\n" << std::flush;
  return RoundEnd::complete;
}

bool past(const std::optional<Clock::time_point>& deadline) {
  return deadline && Clock::now() >= *deadline;
}

// Runs the tasks on `workers` threads, each taking the next task, the largest first.
class Workers {
 public:
  Workers(RoundContext& context, std::vector<CampaignSearchTask>& tasks, RoundResults& results,
          std::atomic<bool>& abort)
      : context_(context), tasks_(tasks), results_(results), abort_(abort), order_(tasks.size()) {
    // The largest searches first, so that the round does not wait on a large one started last
    // (the round's results are recorded in its own order all the same).
    std::iota(order_.begin(), order_.end(), std::size_t{0});
    std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
      return tasks_[a].budget > tasks_[b].budget;
    });
  }

  void start(std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) threads_.emplace_back([this] { work(); });
  }
  void join() {
    for (std::thread& thread : threads_) thread.join();
    threads_.clear();
  }

 private:
  void work() {
    const std::function<bool()> stop = [this] {
      return StopSignalGuard::stop_requested() || abort_.load();
    };
    for (std::size_t taken = next_++; taken < tasks_.size(); taken = next_++) {
      const std::size_t i = order_[taken];
      Slot slot;
      if (stop() || past(context_.deadline)) {
        slot.skipped = true;
      } else {
        CampaignSearchTask& task = tasks_[i];
        if (context_.deadline)
          task.time_limit = std::max(
              1e-3, std::chrono::duration<double>(*context_.deadline - Clock::now()).count());
        try {
          slot.result = run_campaign_search(context_.seeds, context_.simulation, task, stop);
        } catch (const std::exception& error) {
          slot.result.error = std::string("scenfuzz: error: ") + error.what() + "\n";
        }
      }
      results_.put(i, std::move(slot));
    }
  }

  RoundContext& context_;
  std::vector<CampaignSearchTask>& tasks_;
  RoundResults& results_;
  std::atomic<bool>& abort_;
  std::vector<std::size_t> order_;  // the tasks in the order they are started
  std::atomic<std::size_t> next_{0};
  std::vector<std::thread> threads_;
};

}  // namespace

std::string replay_command(const SimulationCommandOptions& simulation,
                           const std::string& scenario_file, std::uint64_t seed,
                           const std::string& scenario) {
  std::string command = "scenfuzz run";
  for (const std::string& path : simulation.map_paths) command += " --map-path " + quoted(path);
  if (!simulation.ego_plugin.empty()) command += " --ego-plugin " + quoted(simulation.ego_plugin);
  if (!scenario.empty()) command += " --scenario " + quoted(scenario);
  return command + " --seed " + std::to_string(seed) + " " + quoted(scenario_file);
}

void RoundRecorder::take(const CampaignSearchTask& task, const RoundSlot& slot) {
  if (end_ == RoundEnd::failed || end_ == RoundEnd::interrupted) return;
  if (!slot.result.error.empty()) {
    context_.err << slot.result.error;
    end_ = RoundEnd::failed;
  } else if (slot.skipped || slot.result.interrupted) {
    end_ = StopSignalGuard::stop_requested() ? RoundEnd::interrupted : RoundEnd::wall_time;
  } else {
    try {
      end_ = record(context_, round_, task, slot.result);
    } catch (const CampaignDbError& error) {
      context_.err << "scenfuzz: error: " << error.what() << "\n";
      end_ = RoundEnd::failed;
    }
    if (end_ == RoundEnd::complete && slot.result.summary.stop == StopReason::time_limit)
      end_ = RoundEnd::wall_time;
  }
}

RoundEnd run_round(RoundContext& context, std::int64_t round,
                   std::vector<CampaignSearchTask> tasks) {
  if (tasks.empty()) return RoundEnd::complete;
  if (context.mpi) return run_round_on_ranks(context, round, std::move(tasks));
  const std::size_t workers = std::max<std::size_t>(1, std::min(context.workers, tasks.size()));
  // Fewer searches than workers: the searches share the threads out.
  for (CampaignSearchTask& task : tasks)
    task.threads = std::max<std::size_t>(1, context.workers / workers);
  RoundResults results(tasks.size());
  std::atomic<bool> abort{false};
  Workers pool(context, tasks, results, abort);
  pool.start(workers);
  RoundRecorder recorder(context, round);
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    recorder.take(tasks[i], results.take(i));
    if (recorder.failed()) abort = true;
  }
  pool.join();
  if (recorder.end() == RoundEnd::complete && past(context.deadline)) return RoundEnd::wall_time;
  return recorder.end();
}

}  // namespace scenfuzz
