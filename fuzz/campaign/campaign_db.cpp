// CampaignDb: the only file that includes sqlite3.h. Statements are prepared per call (a campaign
// writes a few rows per search, so caching them would buy nothing); every change runs inside a
// Transaction, which rolls back unless committed, so an exception half-way leaves no rows.
#include "fuzz/campaign/campaign_db.hpp"

#include <sqlite3.h>

#include <chrono>
#include <ctime>
#include <utility>

#include "lang/demand.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

// Version 2. Later versions add migrations in open(), never edit this text. (Version 1 came
// before `campaign run` and no campaign used it: it is refused, see prepare_schema.)
constexpr const char* kSchema = R"sql(
CREATE TABLE schema_version (version INTEGER NOT NULL);
CREATE TABLE runs (
  id INTEGER PRIMARY KEY,
  started TEXT NOT NULL,
  ended TEXT,
  ego_version TEXT NOT NULL);
CREATE TABLE seeds (
  id INTEGER PRIMARY KEY,
  path TEXT NOT NULL,
  content_hash TEXT NOT NULL,
  UNIQUE (path, content_hash));
CREATE TABLE searches (
  id INTEGER PRIMARY KEY,
  run_id INTEGER NOT NULL REFERENCES runs (id),
  seed_id INTEGER NOT NULL REFERENCES seeds (id),
  algorithm TEXT NOT NULL,
  budget INTEGER NOT NULL CHECK (budget >= 0),
  status TEXT NOT NULL CHECK (status IN ('running', 'done', 'stopped', 'failed')),
  output_folder TEXT NOT NULL,
  round INTEGER NOT NULL CHECK (round >= 0),
  spec_index INTEGER NOT NULL CHECK (spec_index >= 0),
  spec TEXT NOT NULL,
  search_seed INTEGER NOT NULL,
  simulations INTEGER NOT NULL CHECK (simulations >= 0),
  new_modes INTEGER NOT NULL CHECK (new_modes >= 0),
  best_robustness REAL,
  UNIQUE (run_id, round, seed_id, spec_index));
CREATE TABLE evaluations (
  search_id INTEGER NOT NULL REFERENCES searches (id),
  evaluation_index INTEGER NOT NULL,
  robustness REAL,
  finding INTEGER NOT NULL CHECK (finding IN (0, 1)),
  PRIMARY KEY (search_id, evaluation_index)) WITHOUT ROWID;
CREATE TABLE failure_modes (
  id INTEGER PRIMARY KEY,
  seed_id INTEGER NOT NULL REFERENCES seeds (id),
  signature TEXT NOT NULL,
  spec TEXT NOT NULL,
  responsibility TEXT NOT NULL,
  scenario_file TEXT NOT NULL,
  replay_command TEXT NOT NULL,
  first_seen_run INTEGER NOT NULL REFERENCES runs (id),
  last_seen_run INTEGER NOT NULL REFERENCES runs (id),
  status TEXT NOT NULL
    CHECK (status IN ('new', 'still_failing', 'fixed', 'flaky', 'regressed')),
  UNIQUE (seed_id, signature));
CREATE TABLE replays (
  run_id INTEGER NOT NULL REFERENCES runs (id),
  failure_mode_id INTEGER NOT NULL REFERENCES failure_modes (id),
  tried INTEGER NOT NULL CHECK (tried >= 0),
  failing INTEGER NOT NULL CHECK (failing >= 0 AND failing <= tried),
  verdict TEXT NOT NULL CHECK (verdict IN
    ('still_failing', 'regressed', 'fixed', 'flaky', 'not_replayed', 'error')),
  error TEXT NOT NULL,
  PRIMARY KEY (run_id, failure_mode_id)) WITHOUT ROWID;
CREATE TABLE sightings (
  run_id INTEGER NOT NULL REFERENCES runs (id),
  failure_mode_id INTEGER NOT NULL REFERENCES failure_modes (id),
  search_id INTEGER NOT NULL REFERENCES searches (id),
  PRIMARY KEY (run_id, failure_mode_id, search_id)) WITHOUT ROWID;
)sql";

// Version 3: the behaviour-coverage features (docs/coverage.md) each search reached, so that a
// seed's coverage is the union over its searches and a run's over the run's searches.
constexpr const char* kCoverageSchema = R"sql(
CREATE TABLE coverage (
  search_id INTEGER NOT NULL REFERENCES searches (id),
  feature TEXT NOT NULL,
  PRIMARY KEY (search_id, feature)) WITHOUT ROWID;
)sql";

[[noreturn]] void fail(sqlite3* connection, const std::string& doing) {
  throw CampaignDbError("campaign.db: " + doing + ": " + sqlite3_errmsg(connection));
}

void execute(sqlite3* connection, const char* sql, const std::string& doing) {
  if (sqlite3_exec(connection, sql, nullptr, nullptr, nullptr) != SQLITE_OK)
    fail(connection, doing);
}

// A prepared statement with its parameters bound by position (1-based, as SQLite counts).
class Statement {
 public:
  Statement(sqlite3* connection, const char* sql) : connection_(connection) {
    if (sqlite3_prepare_v2(connection, sql, -1, &statement_, nullptr) != SQLITE_OK)
      fail(connection, "preparing a statement");
  }
  ~Statement() { sqlite3_finalize(statement_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int index, std::int64_t value) {
    check(sqlite3_bind_int64(statement_, index, value));
    return *this;
  }
  Statement& bind(int index, std::string_view text) {
    check(sqlite3_bind_text(statement_, index, text.data(), static_cast<int>(text.size()),
                            SQLITE_TRANSIENT));
    return *this;
  }
  // A 64-bit seed, stored as the signed integer with the same bits (SQLite has no unsigned).
  Statement& bind_bits(int index, std::uint64_t value) {
    return bind(index, static_cast<std::int64_t>(value));
  }
  Statement& bind(int index, std::optional<double> value) {
    check(value ? sqlite3_bind_double(statement_, index, *value)
                : sqlite3_bind_null(statement_, index));
    return *this;
  }

  // Ready to run again with new values.
  void reset() {
    sqlite3_reset(statement_);
    sqlite3_clear_bindings(statement_);
  }

  // True with a row to read, false when done.
  bool step() {
    const int status = sqlite3_step(statement_);
    if (status == SQLITE_ROW) return true;
    if (status == SQLITE_DONE) return false;
    fail(connection_, "running a statement");
  }

  std::int64_t integer(int column) { return sqlite3_column_int64(statement_, column); }
  std::optional<double> real(int column) {
    if (sqlite3_column_type(statement_, column) == SQLITE_NULL) return std::nullopt;
    return sqlite3_column_double(statement_, column);
  }
  std::string text(int column) {
    const auto* bytes = sqlite3_column_text(statement_, column);
    if (bytes == nullptr) return {};
    return {reinterpret_cast<const char*>(bytes),
            static_cast<std::size_t>(sqlite3_column_bytes(statement_, column))};
  }

 private:
  void check(int status) {
    if (status != SQLITE_OK) fail(connection_, "binding a value");
  }

  sqlite3* connection_;
  sqlite3_stmt* statement_ = nullptr;
};

// BEGIN IMMEDIATE (the write lock up front, so a transaction never fails half-way for want of
// it); rolled back on destruction unless committed.
class Transaction {
 public:
  explicit Transaction(sqlite3* connection) : connection_(connection) {
    execute(connection_, "BEGIN IMMEDIATE", "starting a transaction");
  }
  ~Transaction() {
    if (!committed_) sqlite3_exec(connection_, "ROLLBACK", nullptr, nullptr, nullptr);
  }
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;

  void commit() {
    execute(connection_, "COMMIT", "committing");
    committed_ = true;
  }

 private:
  sqlite3* connection_;
  bool committed_ = false;
};

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

bool has_table(sqlite3* connection, const char* name) {
  Statement query(connection, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?");
  query.bind(1, std::string_view(name));
  return query.step();
}

// Creates the schema in an empty database, or checks an existing one's version. Empty on
// success, else why the database cannot be used.
std::string prepare_schema(sqlite3* connection) {
  Transaction transaction(connection);
  if (!has_table(connection, "schema_version")) {
    Statement tables(connection, "SELECT count(*) FROM sqlite_master");
    tables.step();
    if (tables.integer(0) != 0)
      return "it is an SQLite database, but not a campaign's (no schema_version table)";
    execute(connection, kSchema, "creating the schema");
    execute(connection, kCoverageSchema, "creating the coverage table");
    Statement version(connection, "INSERT INTO schema_version (version) VALUES (?)");
    version.bind(1, kCampaignSchemaVersion).step();
    transaction.commit();
    return {};
  }
  Statement version(connection, "SELECT version FROM schema_version");
  const std::int64_t found = version.step() ? version.integer(0) : 0;
  if (found == 2) {
    // Schema 2 to 3: the coverage table; the searches recorded before it have none.
    execute(connection, kCoverageSchema, "adding the coverage table");
    execute(connection, "UPDATE schema_version SET version = 3", "updating the schema version");
    transaction.commit();
    return {};
  }
  if (found != kCampaignSchemaVersion)
    return "its schema version is " + std::to_string(found) + ", this scenfuzz reads version " +
           std::to_string(kCampaignSchemaVersion) +
           (found > kCampaignSchemaVersion
                ? " (a newer scenfuzz wrote it)"
                : " (an early development version wrote it, before `campaign run`: move "
                  "campaign.db away and run again to start the campaign's history afresh)");
  transaction.commit();
  return {};
}

// WAL: readers (a report) never block the run and the run never blocks them; synchronous FULL
// makes each committed transaction survive a power cut, not only a killed process.
void configure(sqlite3* connection) {
  sqlite3_busy_timeout(connection, 10000);
  Statement wal(connection, "PRAGMA journal_mode = WAL");
  if (!wal.step() || wal.text(0) != "wal")
    throw CampaignDbError(
        "campaign.db: cannot switch to WAL mode (a file system without shared "
        "memory?)");
  execute(connection, "PRAGMA synchronous = FULL", "setting synchronous");
  execute(connection, "PRAGMA foreign_keys = ON", "enabling foreign keys");
}

SearchStatus search_status(const std::string& name) {
  for (SearchStatus status :
       {SearchStatus::running, SearchStatus::done, SearchStatus::stopped, SearchStatus::failed})
    if (status_name(status) == name) return status;
  // The schema's CHECK admits no other name.
  demand_failed("a search status the schema admits", __FILE__, __LINE__);
}

FailureModeStatus failure_mode_status(const std::string& name) {
  for (FailureModeStatus status :
       {FailureModeStatus::new_mode, FailureModeStatus::still_failing, FailureModeStatus::fixed,
        FailureModeStatus::flaky, FailureModeStatus::regressed})
    if (status_name(status) == name) return status;
  demand_failed("a failure-mode status the schema admits", __FILE__, __LINE__);
}

constexpr const char* kFailureModeColumns =
    "SELECT id, seed_id, signature, spec, responsibility, scenario_file, replay_command, "
    "first_seen_run, last_seen_run, status FROM failure_modes";

CampaignFailureMode read_failure_mode(Statement& row) {
  CampaignFailureMode mode;
  mode.id = row.integer(0);
  mode.record = {row.integer(1), row.text(2), row.text(3), row.text(4), row.text(5), row.text(6)};
  mode.first_seen_run = row.integer(7);
  mode.last_seen_run = row.integer(8);
  mode.status = failure_mode_status(row.text(9));
  return mode;
}

// The searches row and its evaluations, inside the caller's transaction; the search's id.
std::int64_t insert_search(sqlite3* connection, const SearchRecord& search,
                           std::span<const CampaignEvaluation> evaluations,
                           std::int64_t new_modes) {
  Statement insert(connection,
                   "INSERT INTO searches (run_id, seed_id, algorithm, budget, status, "
                   "output_folder, round, spec_index, spec, search_seed, simulations, new_modes, "
                   "best_robustness) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  insert.bind(1, search.run_id)
      .bind(2, search.seed_id)
      .bind(3, std::string_view(search.algorithm))
      .bind(4, static_cast<std::int64_t>(search.budget))
      .bind(5, status_name(search.status))
      .bind(6, std::string_view(search.output_folder))
      .bind(7, search.round)
      .bind(8, search.spec_index)
      .bind(9, std::string_view(search.spec))
      .bind_bits(10, search.search_seed)
      .bind(11, static_cast<std::int64_t>(search.simulations))
      .bind(12, new_modes)
      .bind(13, search.best_robustness)
      .step();
  const std::int64_t id = sqlite3_last_insert_rowid(connection);
  Statement row(connection,
                "INSERT INTO evaluations (search_id, evaluation_index, robustness, finding) "
                "VALUES (?, ?, ?, ?)");
  for (const CampaignEvaluation& evaluation : evaluations) {
    row.bind(1, id)
        .bind(2, evaluation.index)
        .bind(3, evaluation.robustness)
        .bind(4, std::int64_t{evaluation.finding ? 1 : 0})
        .step();
    row.reset();
  }
  return id;
}

struct UpsertedMode {
  CampaignFailureMode mode;
  bool added = false;  // unknown to its seed before
};

// upsert_failure_mode's change, inside the caller's transaction.
UpsertedMode upsert_mode(sqlite3* connection, std::int64_t run_id, const FailureModeRecord& mode) {
  Statement known(connection, "SELECT 1 FROM failure_modes WHERE seed_id = ? AND signature = ?");
  known.bind(1, mode.seed_id).bind(2, std::string_view(mode.signature));
  const bool added = !known.step();
  // A known mode keeps its representative scenario and replay command: the first one found is
  // the one the replays of later runs have been judging.
  Statement insert(connection,
                   "INSERT INTO failure_modes (seed_id, signature, spec, responsibility, "
                   "scenario_file, replay_command, first_seen_run, last_seen_run, status) "
                   "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?7, 'new') "
                   "ON CONFLICT (seed_id, signature) DO UPDATE SET "
                   "status = CASE WHEN first_seen_run = ?7 THEN status "
                   "WHEN status = 'fixed' THEN 'regressed' "
                   "WHEN status = 'regressed' AND (last_seen_run = ?7 OR EXISTS ("
                   "SELECT 1 FROM replays WHERE replays.run_id = ?7 AND "
                   "replays.failure_mode_id = failure_modes.id AND verdict = 'regressed')) "
                   "THEN 'regressed' "
                   "ELSE 'still_failing' END, "
                   "last_seen_run = ?7");
  insert.bind(1, mode.seed_id)
      .bind(2, std::string_view(mode.signature))
      .bind(3, std::string_view(mode.spec))
      .bind(4, std::string_view(mode.responsibility))
      .bind(5, std::string_view(mode.scenario_file))
      .bind(6, std::string_view(mode.replay_command))
      .bind(7, run_id)
      .step();
  Statement find(
      connection,
      (std::string(kFailureModeColumns) + " WHERE seed_id = ? AND signature = ?").c_str());
  find.bind(1, mode.seed_id).bind(2, std::string_view(mode.signature));
  SCENFUZZ_DEMAND(find.step());
  return {read_failure_mode(find), added};
}

}  // namespace

ReplayVerdict replay_verdict(FailureModeStatus before, const ReplayOutcome& outcome) {
  if (!outcome.error.empty()) return {"error", before};
  if (outcome.tried <= 0) return {"not_replayed", before};
  if (outcome.failing >= outcome.tried) {
    if (before == FailureModeStatus::fixed) return {"regressed", FailureModeStatus::regressed};
    return {"still_failing", FailureModeStatus::still_failing};
  }
  if (outcome.failing <= 0) return {"fixed", FailureModeStatus::fixed};
  return {"flaky", FailureModeStatus::flaky};
}

std::string_view status_name(SearchStatus status) {
  switch (status) {
    case SearchStatus::running: return "running";
    case SearchStatus::done: return "done";
    case SearchStatus::stopped: return "stopped";
    case SearchStatus::failed: return "failed";
  }
  demand_failed("a valid SearchStatus", __FILE__, __LINE__);
}

std::string_view status_name(FailureModeStatus status) {
  switch (status) {
    case FailureModeStatus::new_mode: return "new";
    case FailureModeStatus::still_failing: return "still_failing";
    case FailureModeStatus::fixed: return "fixed";
    case FailureModeStatus::flaky: return "flaky";
    case FailureModeStatus::regressed: return "regressed";
  }
  demand_failed("a valid FailureModeStatus", __FILE__, __LINE__);
}

CampaignDbOpening CampaignDb::open(const fs::path& dir) {
  CampaignDbOpening opening;
  CampaignLock lock;
  if (std::string problem = lock.acquire(dir); !problem.empty()) {
    opening.error = std::move(problem);
    return opening;
  }
  const fs::path path = dir / "campaign.db";
  sqlite3* connection = nullptr;
  const int status = sqlite3_open_v2(path.c_str(), &connection,
                                     SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  // From here the object owns the connection (sqlite3_open_v2 gives one even when it fails).
  std::unique_ptr<CampaignDb> db(new CampaignDb(connection, std::move(lock)));
  try {
    if (status != SQLITE_OK) fail(connection, "opening");
    configure(connection);
    if (std::string problem = prepare_schema(connection); !problem.empty())
      throw CampaignDbError(problem);
  } catch (const CampaignDbError& error) {
    opening.error = "cannot use '" + path.string() + "': " + error.what();
    return opening;
  }
  opening.db = std::move(db);
  return opening;
}

CampaignDb::CampaignDb(sqlite3* connection, CampaignLock lock)
    : connection_(connection), lock_(std::move(lock)) {}

// The connection closes before the lock is released (members are destroyed after this body).
CampaignDb::~CampaignDb() { sqlite3_close_v2(connection_); }

std::int64_t CampaignDb::schema_version() {
  Statement version(connection_, "SELECT version FROM schema_version");
  return version.step() ? version.integer(0) : 0;
}

std::int64_t CampaignDb::begin_run(const std::string& ego_version) {
  Transaction transaction(connection_);
  Statement insert(connection_, "INSERT INTO runs (started, ego_version) VALUES (?, ?)");
  insert.bind(1, std::string_view(utc_now())).bind(2, std::string_view(ego_version)).step();
  const std::int64_t id = sqlite3_last_insert_rowid(connection_);
  transaction.commit();
  return id;
}

void CampaignDb::end_run(std::int64_t run_id) {
  Transaction transaction(connection_);
  Statement update(connection_, "UPDATE runs SET ended = ? WHERE id = ?");
  update.bind(1, std::string_view(utc_now())).bind(2, run_id).step();
  transaction.commit();
}

std::int64_t CampaignDb::upsert_seed(const std::string& path, const std::string& content_hash) {
  Transaction transaction(connection_);
  Statement insert(connection_, "INSERT OR IGNORE INTO seeds (path, content_hash) VALUES (?, ?)");
  insert.bind(1, std::string_view(path)).bind(2, std::string_view(content_hash)).step();
  Statement find(connection_, "SELECT id FROM seeds WHERE path = ? AND content_hash = ?");
  find.bind(1, std::string_view(path)).bind(2, std::string_view(content_hash));
  SCENFUZZ_DEMAND(find.step());
  const std::int64_t id = find.integer(0);
  transaction.commit();
  return id;
}

std::int64_t CampaignDb::record_search(const SearchRecord& search,
                                       std::span<const CampaignEvaluation> evaluations) {
  Transaction transaction(connection_);
  const std::int64_t id = insert_search(connection_, search, evaluations, search.new_modes);
  transaction.commit();
  return id;
}

RecordedSearch CampaignDb::record_search_result(const SearchRecord& search,
                                                std::span<const CampaignEvaluation> evaluations,
                                                std::span<const FailureModeRecord> modes,
                                                std::span<const std::string> coverage) {
  Transaction transaction(connection_);
  RecordedSearch recorded;
  std::vector<std::int64_t> found;
  for (const FailureModeRecord& mode : modes) {
    const UpsertedMode upserted = upsert_mode(connection_, search.run_id, mode);
    if (upserted.added) ++recorded.new_modes;
    found.push_back(upserted.mode.id);
  }
  recorded.search_id = insert_search(connection_, search, evaluations, recorded.new_modes);
  // Which modes this search found: the report's "found in run R" (the modes' last_seen_run
  // forgets earlier runs).
  Statement sighting(connection_,
                     "INSERT OR IGNORE INTO sightings (run_id, failure_mode_id, search_id) "
                     "VALUES (?, ?, ?)");
  for (const std::int64_t mode_id : found) {
    sighting.bind(1, search.run_id).bind(2, mode_id).bind(3, recorded.search_id).step();
    sighting.reset();
  }
  Statement feature(connection_,
                    "INSERT OR IGNORE INTO coverage (search_id, feature) VALUES (?, ?)");
  for (const std::string& name : coverage) {
    feature.bind(1, recorded.search_id).bind(2, std::string_view(name)).step();
    feature.reset();
  }
  transaction.commit();
  return recorded;
}

CampaignFailureMode CampaignDb::upsert_failure_mode(std::int64_t run_id,
                                                    const FailureModeRecord& mode) {
  Transaction transaction(connection_);
  CampaignFailureMode stored = upsert_mode(connection_, run_id, mode).mode;
  transaction.commit();
  return stored;
}

CampaignReplay CampaignDb::record_replay(std::int64_t run_id, std::int64_t failure_mode_id,
                                         const ReplayOutcome& outcome) {
  Transaction transaction(connection_);
  Statement find(connection_, (std::string(kFailureModeColumns) + " WHERE id = ?").c_str());
  find.bind(1, failure_mode_id);
  if (!find.step())
    throw CampaignDbError("campaign.db: no failure mode " + std::to_string(failure_mode_id));
  const CampaignFailureMode mode = read_failure_mode(find);
  const ReplayVerdict verdict = replay_verdict(mode.status, outcome);
  const CampaignReplay replay{run_id,          failure_mode_id, outcome.tried,
                              outcome.failing, verdict.verdict, outcome.error};
  Statement insert(connection_,
                   "INSERT INTO replays (run_id, failure_mode_id, tried, failing, verdict, error) "
                   "VALUES (?, ?, ?, ?, ?, ?)");
  insert.bind(1, run_id)
      .bind(2, failure_mode_id)
      .bind(3, std::int64_t{outcome.tried})
      .bind(4, std::int64_t{outcome.failing})
      .bind(5, std::string_view(verdict.verdict))
      .bind(6, std::string_view(outcome.error))
      .step();
  Statement update(connection_, "UPDATE failure_modes SET status = ? WHERE id = ?");
  update.bind(1, status_name(verdict.status)).bind(2, failure_mode_id).step();
  transaction.commit();
  return replay;
}

void CampaignDb::set_failure_mode_status(std::int64_t failure_mode_id, FailureModeStatus status) {
  Transaction transaction(connection_);
  Statement update(connection_, "UPDATE failure_modes SET status = ? WHERE id = ?");
  update.bind(1, status_name(status)).bind(2, failure_mode_id).step();
  if (sqlite3_changes(connection_) != 1)
    throw CampaignDbError("campaign.db: no failure mode " + std::to_string(failure_mode_id));
  transaction.commit();
}

std::vector<CampaignRun> CampaignDb::list_runs() {
  Statement rows(connection_, "SELECT id, started, ended, ego_version FROM runs ORDER BY id");
  std::vector<CampaignRun> runs;
  while (rows.step()) runs.push_back({rows.integer(0), rows.text(1), rows.text(2), rows.text(3)});
  return runs;
}

std::vector<CampaignSeed> CampaignDb::list_seeds() {
  Statement rows(connection_, "SELECT id, path, content_hash FROM seeds ORDER BY id");
  std::vector<CampaignSeed> seeds;
  while (rows.step()) seeds.push_back({rows.integer(0), rows.text(1), rows.text(2)});
  return seeds;
}

std::vector<CampaignSearch> CampaignDb::list_searches() {
  Statement rows(connection_,
                 "SELECT id, run_id, seed_id, algorithm, budget, status, output_folder, round, "
                 "spec_index, spec, search_seed, simulations, new_modes, best_robustness "
                 "FROM searches ORDER BY id");
  std::vector<CampaignSearch> searches;
  while (rows.step()) {
    CampaignSearch search;
    search.id = rows.integer(0);
    search.record = {rows.integer(1),
                     rows.integer(2),
                     rows.text(3),
                     static_cast<std::uint64_t>(rows.integer(4)),
                     search_status(rows.text(5)),
                     rows.text(6),
                     rows.integer(7),
                     rows.integer(8),
                     rows.text(9),
                     static_cast<std::uint64_t>(rows.integer(10)),
                     static_cast<std::uint64_t>(rows.integer(11)),
                     rows.integer(12),
                     rows.real(13)};
    searches.push_back(std::move(search));
  }
  return searches;
}

std::vector<CampaignEvaluation> CampaignDb::list_evaluations(std::int64_t search_id) {
  Statement rows(connection_,
                 "SELECT evaluation_index, robustness, finding FROM evaluations "
                 "WHERE search_id = ? ORDER BY evaluation_index");
  rows.bind(1, search_id);
  std::vector<CampaignEvaluation> evaluations;
  while (rows.step()) evaluations.push_back({rows.integer(0), rows.real(1), rows.integer(2) != 0});
  return evaluations;
}

std::vector<CampaignReplay> CampaignDb::list_replays() {
  Statement rows(connection_,
                 "SELECT run_id, failure_mode_id, tried, failing, verdict, error FROM replays "
                 "ORDER BY run_id, failure_mode_id");
  std::vector<CampaignReplay> replays;
  while (rows.step())
    replays.push_back({rows.integer(0), rows.integer(1), static_cast<int>(rows.integer(2)),
                       static_cast<int>(rows.integer(3)), rows.text(4), rows.text(5)});
  return replays;
}

std::vector<CampaignSighting> CampaignDb::list_sightings() {
  Statement rows(connection_,
                 "SELECT run_id, failure_mode_id, search_id FROM sightings "
                 "ORDER BY run_id, failure_mode_id, search_id");
  std::vector<CampaignSighting> sightings;
  while (rows.step()) sightings.push_back({rows.integer(0), rows.integer(1), rows.integer(2)});
  return sightings;
}

std::vector<std::string> CampaignDb::list_coverage(std::int64_t search_id) {
  if (!has_table(connection_, "coverage")) return {};
  Statement rows(connection_, "SELECT feature FROM coverage WHERE search_id = ? ORDER BY feature");
  rows.bind(1, search_id);
  std::vector<std::string> features;
  while (rows.step()) features.push_back(rows.text(0));
  return features;
}

std::optional<CampaignRun> CampaignDb::unfinished_run() {
  Statement row(connection_,
                "SELECT id, started, ended, ego_version FROM runs ORDER BY id DESC LIMIT 1");
  if (!row.step() || !row.text(2).empty()) return std::nullopt;
  return CampaignRun{row.integer(0), row.text(1), row.text(2), row.text(3)};
}

std::vector<CampaignFailureMode> CampaignDb::list_failure_modes() {
  Statement rows(connection_, (std::string(kFailureModeColumns) + " ORDER BY id").c_str());
  std::vector<CampaignFailureMode> modes;
  while (rows.step()) modes.push_back(read_failure_mode(rows));
  return modes;
}

// --- Reading without the run lock (the report) ---

namespace {

// The schema check of a read-only connection: it may not create the schema, only find it.
std::string check_readable_schema(sqlite3* connection) {
  if (!has_table(connection, "schema_version"))
    return "it is an SQLite database, but not a campaign's (no schema_version table)";
  Statement version(connection, "SELECT version FROM schema_version");
  const std::int64_t found = version.step() ? version.integer(0) : 0;
  // Version 2 differs only by the coverage table, which list_coverage does without.
  if (found == kCampaignSchemaVersion || found == 2) return {};
  return "its schema version is " + std::to_string(found) + ", this scenfuzz reads version " +
         std::to_string(kCampaignSchemaVersion) +
         (found > kCampaignSchemaVersion ? " (a newer scenfuzz wrote it)" : "");
}

}  // namespace

CampaignDbOpening CampaignDb::open_for_reading(const fs::path& dir) {
  CampaignDbOpening opening;
  const fs::path path = dir / "campaign.db";
  std::error_code error;
  if (!fs::is_regular_file(path, error)) {
    opening.error = "'" + dir.string() + "' is not a campaign folder: it has no campaign.db";
    return opening;
  }
  sqlite3* connection = nullptr;
  const int status = sqlite3_open_v2(path.c_str(), &connection, SQLITE_OPEN_READONLY, nullptr);
  // An unlocked CampaignLock: this connection never writes.
  std::unique_ptr<CampaignDb> db(new CampaignDb(connection, CampaignLock{}));
  try {
    if (status != SQLITE_OK) fail(connection, "opening");
    // A reader may meet a checkpoint in progress: wait for it rather than fail.
    sqlite3_busy_timeout(connection, 10000);
    if (std::string problem = check_readable_schema(connection); !problem.empty())
      throw CampaignDbError(problem);
  } catch (const CampaignDbError& failure) {
    opening.error = "cannot read '" + path.string() + "': " + failure.what();
    return opening;
  }
  opening.db = std::move(db);
  return opening;
}

}  // namespace scenfuzz
