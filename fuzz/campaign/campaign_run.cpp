// run_campaign: the run's phases in order (config, seeds, lock, run, replay, rounds, end) and its
// exit status.
#include "fuzz/campaign/campaign_run.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "fuzz/atomic_file.hpp"
#include "fuzz/campaign/budget_schedule.hpp"
#include "fuzz/campaign/campaign_config.hpp"
#include "fuzz/campaign/campaign_round.hpp"
#include "fuzz/campaign/campaign_seeds.hpp"
#include "fuzz/campaign/junit_report.hpp"
#include "fuzz/campaign/mode_files.hpp"
#include "fuzz/campaign/mpi_round.hpp"
#include "fuzz/campaign/regression_replay.hpp"
#include "fuzz/campaign/run_exit_status.hpp"
#include "fuzz/campaign/run_json.hpp"
#include "fuzz/campaign/run_summary.hpp"
#include "fuzz/cli.hpp"
#include "fuzz/report_format.hpp"
#include "fuzz/stop_signals.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// Makes the campaign folder the current one while it lives, so that every path the run writes
// (search folders, finding headers, modes, replay commands) is relative to it and the same
// wherever the folder sits.
class CurrentFolder {
 public:
  // Empty `error` on success.
  CurrentFolder(const fs::path& dir, std::string& error) {
    std::error_code failure;
    previous_ = fs::current_path(failure);
    if (!failure) fs::current_path(dir, failure);
    if (failure)
      error = "cannot enter the campaign folder '" + dir.string() + "': " + failure.message();
    entered_ = !failure;
  }
  ~CurrentFolder() {
    std::error_code ignored;
    if (entered_) fs::current_path(previous_, ignored);
  }
  CurrentFolder(const CurrentFolder&) = delete;
  CurrentFolder& operator=(const CurrentFolder&) = delete;

 private:
  fs::path previous_;
  bool entered_ = false;
};

std::optional<CampaignConfig> read_config(const fs::path& dir, std::ostream& err) {
  const fs::path path = dir / "campaign.toml";
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    err << "scenfuzz: error: cannot read '" << path.string() << "': " << std::strerror(errno)
        << " (start a campaign with 'scenfuzz campaign init DIR FILES...')\n";
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  CampaignConfigResult parsed = parse_campaign_config(text.str(), path.string());
  err << format_diagnostics(SourceFile(path.string(), text.str()), parsed.diagnostics);
  return std::move(parsed.config);
}

// The unfinished run of the same ego, continued; else a new one (an unfinished run of another
// ego version is closed first: its version can no longer be tested).
std::int64_t run_to_use(CampaignDb& db, const std::string& ego_version, std::ostream& out) {
  if (const std::optional<CampaignRun> last = db.unfinished_run()) {
    if (last->ego_version == ego_version) {
      out << "continuing run " << last->id << " (started " << last->started << ")\n" << std::flush;
      return last->id;
    }
    db.end_run(last->id);
  }
  const std::int64_t run = db.begin_run(ego_version);
  out << "run " << run << " of ego version " << ego_version << "\n" << std::flush;
  return run;
}

// The regression replay: every failure mode known before this run and not replayed in it yet.
// False when a signal stopped it.
bool replay_known_modes(CampaignDb& db, std::int64_t run, const ModeReplayer& replay,
                        std::ostream& out) {
  std::set<std::int64_t> done;
  for (const CampaignReplay& replayed : db.list_replays())
    if (replayed.run_id == run) done.insert(replayed.failure_mode_id);
  std::map<std::string, int> verdicts;
  for (const CampaignFailureMode& mode : db.list_failure_modes()) {
    if (mode.first_seen_run >= run || done.count(mode.id)) continue;
    if (StopSignalGuard::stop_requested()) return false;
    ++verdicts[db.record_replay(run, mode.id, replay(mode)).verdict];
  }
  if (!verdicts.empty()) {
    out << "regression replay:";
    for (const auto& [verdict, count] : verdicts) out << " " << verdict << " " << count;
    out << "\n";
  }
  return true;
}

// The complete rounds of this run before `round`, as the schedule reads them.
std::vector<std::vector<ArmRound>> history(const std::vector<CampaignSearch>& searches,
                                           const CampaignSeeds& seeds, std::int64_t run,
                                           std::int64_t round) {
  std::map<std::pair<std::int64_t, std::int64_t>, std::size_t> arm_of;
  for (std::size_t a = 0; a < seeds.arms.size(); ++a)
    arm_of[{seeds.seeds[seeds.arms[a].seed].id, static_cast<std::int64_t>(seeds.arms[a].spec)}] = a;
  std::vector<std::vector<ArmRound>> rounds(static_cast<std::size_t>(round),
                                            std::vector<ArmRound>(seeds.arms.size()));
  for (const CampaignSearch& search : searches) {
    const SearchRecord& r = search.record;
    const auto arm = arm_of.find({r.seed_id, r.spec_index});
    if (r.run_id != run || r.round >= round || arm == arm_of.end()) continue;
    rounds[static_cast<std::size_t>(r.round)][arm->second] = {
        true, r.simulations, static_cast<std::size_t>(r.new_modes), r.best_robustness};
  }
  return rounds;
}

// The round's searches not recorded yet.
std::vector<CampaignSearchTask> round_tasks(const std::vector<CampaignSearch>& searches,
                                            const CampaignSeeds& seeds, std::uint64_t base_seed,
                                            std::int64_t run, std::int64_t round,
                                            const std::vector<std::uint64_t>& budgets) {
  std::set<std::pair<std::int64_t, std::int64_t>> recorded;
  for (const CampaignSearch& search : searches)
    if (search.record.run_id == run && search.record.round == round)
      recorded.insert({search.record.seed_id, search.record.spec_index});
  std::vector<CampaignSearchTask> tasks;
  for (std::size_t a = 0; a < seeds.arms.size(); ++a) {
    const std::int64_t seed_id = seeds.seeds[seeds.arms[a].seed].id;
    const std::size_t spec = seeds.arms[a].spec;
    if (budgets[a] == 0 || recorded.count({seed_id, static_cast<std::int64_t>(spec)})) continue;
    CampaignSearchTask task;
    task.arm = a;
    task.budget = budgets[a];
    task.seed = campaign_search_seed(base_seed, run, round, seed_id, spec);
    task.folder = campaign_search_folder(run, round, seed_id, spec);
    tasks.push_back(std::move(task));
  }
  return tasks;
}

// Plans and runs rounds until the budget is spent, the wall time is up, a signal or an error.
RoundEnd run_rounds(RoundContext& context, const CampaignConfig& config) {
  ScheduleInput schedule;
  for (const CampaignArm& arm : context.seeds.arms) schedule.weights.push_back(arm.weight);
  schedule.total = config.budget_simulations;
  for (std::int64_t round = 0;; ++round) {
    const std::vector<CampaignSearch> searches = context.db.list_searches();
    schedule.rounds = history(searches, context.seeds, context.run, round);
    const std::vector<std::uint64_t> budgets = plan_round(schedule);
    if (std::all_of(budgets.begin(), budgets.end(), [](std::uint64_t b) { return b == 0; }))
      return RoundEnd::complete;
    const RoundEnd end = run_round(
        context, round,
        round_tasks(searches, context.seeds, config.search.seed, context.run, round, budgets));
    if (end != RoundEnd::complete) return end;
  }
}

std::size_t worker_count(const CampaignRunOptions& options, const CampaignConfig& config) {
  const std::uint64_t jobs = options.jobs ? *options.jobs : config.search.jobs;
  if (jobs > 0) return static_cast<std::size_t>(jobs);
  return std::max(1u, std::thread::hardware_concurrency());
}

// The failure modes by status, and the exit status in words, for people.
void print_ending(const RunSummary& summary, RoundEnd end, std::ostream& progress,
                  std::ostream& err) {
  if (end == RoundEnd::interrupted)
    err << "scenfuzz: interrupted: every finished search is recorded; run 'scenfuzz campaign "
           "run' on the folder again to continue run "
        << summary.run.id << "\n";
  else
    progress << "run " << summary.run.id << " ended"
             << (end == RoundEnd::wall_time ? " at the wall time" : "") << "\n";
  std::map<std::string, int> statuses;
  for (const RunFailureMode& mode : summary.failure_modes)
    ++statuses[std::string(status_name(mode.mode.status))];
  progress << "failure modes:";
  for (const auto& [status, count] : statuses) progress << " " << status << " " << count;
  if (statuses.empty()) progress << " none";
  progress << "\nexit status " << run_exit_reason(summary) << "\n";
}

// The run's summary from the database (so a continued run counts what its killed part did),
// printed, written as JUnit XML and JSON as asked; its exit status.
int report(CampaignDb& db, std::int64_t run, RoundEnd end, const CampaignRunOptions& options,
           const std::string& campaign, std::ostream& out, std::ostream& err) {
  const RunSummary summary = load_run_summary(db, run, campaign);
  print_ending(summary, end, options.json ? err : out, err);
  if (!options.junit.empty()) {
    if (const std::string problem = write_file_atomically(options.junit, junit_xml(summary));
        !problem.empty()) {
      err << "scenfuzz: error: --junit: " << problem << "\n";
      return kExitBadInput;
    }
  }
  if (options.json) out << run_json(summary).dump() << "\n";
  return run_exit_status(summary);
}

// The run once the campaign folder is the current one and the seeds are loaded.
int run_in_folder(const CampaignRunOptions& options, const CampaignConfig& config,
                  CampaignSeeds& seeds, const ModeReplayer& replay, MpiSession* mpi,
                  std::ostream& out, std::ostream& err) {
  std::ostream& progress = options.json ? err : out;
  CampaignDbOpening opening = CampaignDb::open(".");
  if (!opening.db) {
    err << "scenfuzz: error: " << opening.error << "\n";
    return kExitBadInput;
  }
  CampaignDb& db = *opening.db;
  remove_mode_temporaries(".");
  StopSignalGuard guard;
  for (LoadedSeed& seed : seeds.seeds) seed.id = db.upsert_seed(seed.path, seed.content_hash);
  const std::int64_t run = run_to_use(db, config.ego_version, progress);
  const SimulationCommandOptions simulation = campaign_simulation(config);
  MpiPoolTimes mpi_times;
  mpi_times.dead_after_seconds = options.worker_timeout;
  RoundContext context{db,
                       seeds,
                       simulation,
                       run,
                       worker_count(options, config),
                       std::nullopt,
                       progress,
                       err,
                       mpi && mpi->size() > 1 ? mpi : nullptr,
                       mpi_times};
  context.tmin = config.search.tmin;
  if (config.budget_wall_seconds)
    context.deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(
                           std::chrono::duration<double>(*config.budget_wall_seconds));
  RoundEnd end = replay_known_modes(db, run, replay, progress) ? run_rounds(context, config)
                                                               : RoundEnd::interrupted;
  if (end == RoundEnd::failed) return kExitBadInput;
  if (end != RoundEnd::interrupted) db.end_run(run);
  return report(db, run, end, options, config.name, out, err);
}

// --junit FILE is relative to where scenfuzz was started, not to the campaign folder: made
// absolute before the run enters the folder. False (after saying why) when its folder does not
// exist: refused before the run, not after hours of it.
bool absolute_junit_path(CampaignRunOptions& options, std::ostream& err) {
  if (options.junit.empty()) return true;
  const std::string given = options.junit;
  options.junit = fs::absolute(options.junit).string();
  std::error_code error;
  if (fs::is_directory(fs::path(options.junit).parent_path(), error)) return true;
  err << "scenfuzz: error: --junit '" << given << "': its folder does not exist: nothing was run\n";
  return false;
}

}  // namespace

ModeReplayer campaign_replayer(const CampaignConfig& config) {
  ReplaySettings settings;
  settings.simulation = campaign_simulation(config);
  // The run's current folder is the campaign folder, which the mode's paths are relative to.
  return [settings](const CampaignFailureMode& mode) {
    return replay_failure_mode(".", mode, settings);
  };
}

int run_campaign(const CampaignRunOptions& options, std::ostream& out, std::ostream& err) {
  return run_campaign(options, ModeReplayer(), out, err);
}

int run_campaign(const CampaignRunOptions& given, const ModeReplayer& replay, std::ostream& out,
                 std::ostream& err) {
  // Under mpirun every rank reads the campaign and its seeds; rank 0 runs the campaign and the
  // others serve its searches (mpi_round.hpp), saying nothing unless they fail.
  std::optional<MpiSession> mpi;
  if (launched_by_mpirun()) {
    try {
      mpi.emplace();
    } catch (const std::runtime_error& error) {
      err << "scenfuzz: error: " << error.what() << "\n";
      return kExitBadInput;
    }
  }
  const bool worker = mpi && mpi->rank() != 0;
  std::ostringstream quiet;
  std::ostream& said = worker ? quiet : err;
  const std::optional<CampaignConfig> config = read_config(given.dir, said);
  if (!config) return err << quiet.str(), kExitBadInput;
  CampaignRunOptions options = given;
  if (!absolute_junit_path(options, err)) return kExitBadInput;
  const ModeReplayer replayer = replay ? replay : campaign_replayer(*config);
  std::string problem;
  CurrentFolder inside(options.dir, problem);
  if (!problem.empty()) {
    err << "scenfuzz: error: " << problem << "\n";
    return kExitBadInput;
  }
  const SimulationCommandOptions simulation = campaign_simulation(*config);
  std::optional<CampaignSeeds> seeds = load_campaign_seeds(*config, simulation, said);
  if (!seeds) {
    err << quiet.str()
        << "scenfuzz: error: the campaign's seeds have errors (paths are relative to '"
        << options.dir << "'): nothing was run\n";
    return kExitBadInput;
  }
  if (worker) {
    serve_campaign_searches(*mpi, *seeds, simulation, worker_count(options, *config));
    return kExitSuccess;
  }
  try {
    return run_in_folder(options, *config, *seeds, replayer, mpi ? &*mpi : nullptr, out, err);
  } catch (const CampaignDbError& error) {
    err << "scenfuzz: error: " << error.what() << "\n";
    return kExitBadInput;
  }
}

}  // namespace scenfuzz
