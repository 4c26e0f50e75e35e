// A campaign's database, DIR/campaign.db (SQLite, WAL): the single source of truth for its runs,
// seeds (by content hash: an edited seed is a new seed), searches, their evaluations, and the
// failure modes found. Every state change is one transaction, so a killed process loses at most
// the change in flight. Opening a campaign for a run locks it (campaign_lock.hpp): a second run
// is refused, naming the first. docs/campaigns.md describes the schema.
//
// SQLite failures after a successful open (a full disk, a database corrupted under us, a broken
// constraint) throw CampaignDbError; the state change in flight is rolled back first.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz/campaign/campaign_lock.hpp"
#include "fuzz/campaign/replay_outcome.hpp"

struct sqlite3;  // sqlite3.h is for campaign_db.cpp alone

namespace scenfuzz {

class CampaignDbError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The schema this build reads and writes; schema_version holds the database's. Version 1 (before
// `campaign run` existed) lacked the searches' round and arm and the replays table; such a
// database is refused with a message saying to start the campaign's database afresh. Version 2
// lacked the coverage table: a run adds it (its searches then have no coverage recorded) and a
// report reads a version-2 database as one without coverage.
inline constexpr std::int64_t kCampaignSchemaVersion = 3;

enum class SearchStatus { running, done, stopped, failed };
enum class FailureModeStatus { new_mode, still_failing, fixed, flaky, regressed };

// The names stored in the database ("new", "still_failing", ...).
std::string_view status_name(SearchStatus status);
std::string_view status_name(FailureModeStatus status);

struct CampaignRun {
  std::int64_t id = 0;
  std::string started;  // UTC, ISO 8601 ("2026-11-27T02:00:00Z")
  std::string ended;    // empty while running, or when the run was killed
  std::string ego_version;
};

struct CampaignSeed {
  std::int64_t id = 0;
  std::string path;          // relative to the campaign folder
  std::string content_hash;  // content_hash.hpp
};

struct SearchRecord {
  std::int64_t run_id = 0;
  std::int64_t seed_id = 0;
  std::string algorithm;
  std::uint64_t budget = 0;  // simulations it was given
  SearchStatus status = SearchStatus::done;
  std::string output_folder;  // relative to the campaign folder
  // Where the run's schedule put it (budget_schedule.hpp): the round, and the arm's spec (its
  // index among the seed's objectives, and its name).
  std::int64_t round = 0;
  std::int64_t spec_index = 0;
  std::string spec;
  std::uint64_t search_seed = 0;  // the search's --seed
  std::uint64_t simulations = 0;  // spent: judged and failed evaluations
  // Failure modes unknown to the campaign before this search was recorded (set by
  // record_search_result; what the schedule rewards).
  std::int64_t new_modes = 0;
  std::optional<double> best_robustness;  // lowest robustness of its spec; none if none judged
};

struct CampaignSearch {
  std::int64_t id = 0;
  SearchRecord record;
};

// One evaluation of a search, compactly: where it was in the search, the robustness of its
// objective (nullopt: not judged), whether it was a finding.
struct CampaignEvaluation {
  std::int64_t index = 0;
  std::optional<double> robustness;
  bool finding = false;
};

// What a search reports about a failure mode it found.
struct FailureModeRecord {
  std::int64_t seed_id = 0;
  std::string signature;       // the failure-mode signature, unique per seed
  std::string spec;            // the violated spec
  std::string responsibility;  // ego, other, shared, or empty
  std::string scenario_file;   // the representative concrete scenario, named by content hash
  std::string replay_command;  // reproduces it
};

struct CampaignFailureMode {
  std::int64_t id = 0;
  FailureModeRecord record;
  std::int64_t first_seen_run = 0;
  std::int64_t last_seen_run = 0;
  FailureModeStatus status = FailureModeStatus::new_mode;
};

// The regression replay's verdict on one failure mode in one run.
struct CampaignReplay {
  std::int64_t run_id = 0;
  std::int64_t failure_mode_id = 0;
  int tried = 0;
  int failing = 0;
  // "still_failing", "regressed", "fixed", "flaky" (the status it set), "not_replayed" (tried 0:
  // the status stays) or "error" (the status stays).
  std::string verdict;
  std::string error;  // why the mode could not be replayed (verdict "error"); else empty
};

// A search that found a failure mode (new to the campaign or not): what says a mode was found
// in a run, which the mode's last_seen_run forgets once a later run finds it.
struct CampaignSighting {
  std::int64_t run_id = 0;
  std::int64_t failure_mode_id = 0;
  std::int64_t search_id = 0;
};

// How the regression replay's outcome moves a mode's status: every seed failing: still_failing
// (regressed when it was fixed); none: fixed; some: flaky; nothing tried or an error: unchanged.
// The verdict as CampaignReplay::verdict names it, and the status it leaves.
struct ReplayVerdict {
  std::string verdict;
  FailureModeStatus status = FailureModeStatus::new_mode;
};
ReplayVerdict replay_verdict(FailureModeStatus before, const ReplayOutcome& outcome);

// record_search_result's answer.
struct RecordedSearch {
  std::int64_t search_id = 0;
  std::int64_t new_modes = 0;
};

class CampaignDb;

// open()'s result: a database, or why there is none.
struct CampaignDbOpening {
  std::unique_ptr<CampaignDb> db;
  std::string error;
};

class CampaignDb {
 public:
  // Locks the campaign folder `dir` for a run, then creates DIR/campaign.db with the current
  // schema or opens it, checking its schema version. Never throws; an error names the problem
  // (another run holds the campaign; not a database; a newer schema; cannot write).
  static CampaignDbOpening open(const std::filesystem::path& dir);

  ~CampaignDb();
  CampaignDb(const CampaignDb&) = delete;
  CampaignDb& operator=(const CampaignDb&) = delete;

  std::int64_t schema_version();

  // A run starts now with the ego `ego_version`; end_run records when it ended.
  std::int64_t begin_run(const std::string& ego_version);
  void end_run(std::int64_t run_id);
  // The latest run when it has not ended (killed or interrupted): the one to continue.
  std::optional<CampaignRun> unfinished_run();

  // The seed with this path and content, added if new; its id.
  std::int64_t upsert_seed(const std::string& path, const std::string& content_hash);

  // The search and its evaluations, together or not at all; the search's id.
  std::int64_t record_search(const SearchRecord& search,
                             std::span<const CampaignEvaluation> evaluations);

  // A campaign search's whole result in one transaction: the search, its evaluations, and the
  // failure modes it found (each as upsert_failure_mode, and each a sighting), so that a kill
  // never leaves a search without its modes. `search.new_modes` is ignored: the modes its seed did
  // not have before are counted and stored with it.
  // `coverage`: the behaviour-coverage features the search reached (its summary.json's), stored
  // in the same transaction.
  RecordedSearch record_search_result(const SearchRecord& search,
                                      std::span<const CampaignEvaluation> evaluations,
                                      std::span<const FailureModeRecord> modes,
                                      std::span<const std::string> coverage = {});

  // The regression replay of one failure mode in a run, with the status its verdict sets, in one
  // transaction; a second replay of the same mode in the same run is refused (CampaignDbError).
  CampaignReplay record_replay(std::int64_t run_id, std::int64_t failure_mode_id,
                               const ReplayOutcome& outcome);

  // A failure mode found in run `run_id`. New to its seed: added as new, first and last seen in
  // this run. Known: last seen moves to this run, and its status becomes still_failing (a fixed
  // one: regressed; one first seen in this very run stays new; one regressed in this very run,
  // by an earlier search or by this run's replay, stays regressed). Returns it as stored.
  CampaignFailureMode upsert_failure_mode(std::int64_t run_id, const FailureModeRecord& mode);
  // Sets a known failure mode's status (regression replay decides it).
  void set_failure_mode_status(std::int64_t failure_mode_id, FailureModeStatus status);

  std::vector<CampaignRun> list_runs();
  std::vector<CampaignSeed> list_seeds();
  std::vector<CampaignSearch> list_searches();
  std::vector<CampaignEvaluation> list_evaluations(std::int64_t search_id);
  std::vector<CampaignFailureMode> list_failure_modes();
  std::vector<CampaignReplay> list_replays();      // by run, then failure mode
  std::vector<CampaignSighting> list_sightings();  // by run, failure mode, then search
  // The features a search reached, sorted; none for a version-2 database.
  std::vector<std::string> list_coverage(std::int64_t search_id);

  // --- Reading without the run lock (the report) ---
  // Opens an existing DIR/campaign.db read-only, without taking the campaign's lock, so that a
  // report can be written while a run runs (in WAL mode a reader never blocks the writer). Never
  // creates or changes the database; never throws. An error names the problem (no campaign.db;
  // not a database; not a campaign's; another schema version). Writing through the result throws
  // CampaignDbError.
  static CampaignDbOpening open_for_reading(const std::filesystem::path& dir);

 private:
  CampaignDb(sqlite3* connection, CampaignLock lock);

  sqlite3* connection_;  // open while the object lives
  CampaignLock lock_;
};

}  // namespace scenfuzz
