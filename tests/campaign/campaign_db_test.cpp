// The campaign database: created with its schema in WAL mode, reopened intact, seeds keyed by
// content, failure modes' first/last seen and status, state changes all-or-nothing, and one run
// per campaign folder at a time.
#include "fuzz/campaign/campaign_db.hpp"

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "fuzz/content_hash.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

// Rewrites the schema version of the database at `path`, as an older scenfuzz would have left it.
void sqlite_set_version(const fs::path& path, int version) {
  sqlite3* connection = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &connection), SQLITE_OK);
  const std::string sql = "UPDATE schema_version SET version = " + std::to_string(version);
  EXPECT_EQ(sqlite3_exec(connection, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(connection);
}

class CampaignDbTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scenfuzz_campaign_db_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  std::unique_ptr<CampaignDb> open() {
    CampaignDbOpening opening = CampaignDb::open(dir_);
    EXPECT_TRUE(opening.db) << opening.error;
    return std::move(opening.db);
  }

  FailureModeRecord mode(std::int64_t seed_id, const std::string& signature) const {
    return {seed_id,
            signature,
            "spec1",
            "ego",
            "0123456789abcdef.avu",
            "scenfuzz run 0123456789abcdef.avu"};
  }

  static SearchRecord search_record(std::int64_t run, std::int64_t seed, std::uint64_t budget,
                                    const std::string& folder, std::int64_t round = 0) {
    SearchRecord search;
    search.run_id = run;
    search.seed_id = seed;
    search.algorithm = "ga";
    search.budget = budget;
    search.output_folder = folder;
    search.round = round;
    search.spec = "spec1";
    return search;
  }

  fs::path dir_;
};

TEST_F(CampaignDbTest, CreatesTheSchemaInWalMode) {
  {
    auto db = open();
    ASSERT_TRUE(db);
    EXPECT_EQ(db->schema_version(), kCampaignSchemaVersion);
    EXPECT_TRUE(db->list_runs().empty());
    EXPECT_TRUE(db->list_seeds().empty());
    EXPECT_TRUE(db->list_searches().empty());
    EXPECT_TRUE(db->list_failure_modes().empty());
  }
  // The file format bytes 18 and 19 of an SQLite header are 2 in WAL mode (1: rollback journal).
  std::ifstream file(dir_ / "campaign.db", std::ios::binary);
  char header[20] = {};
  ASSERT_TRUE(file.read(header, sizeof header));
  EXPECT_EQ(std::string(header, 15), "SQLite format 3");
  EXPECT_EQ(header[18], 2);
  EXPECT_EQ(header[19], 2);
}

TEST_F(CampaignDbTest, ReopensWithEverythingKept) {
  std::int64_t run = 0, seed = 0;
  {
    auto db = open();
    ASSERT_TRUE(db);
    run = db->begin_run("abc123");
    seed = db->upsert_seed("corpus/a.avu", content_hash("scenario a"));
    db->upsert_failure_mode(run, mode(seed, "collision|npc1|ego"));
    db->end_run(run);
  }
  auto db = open();
  ASSERT_TRUE(db);
  EXPECT_EQ(db->schema_version(), kCampaignSchemaVersion);
  const std::vector<CampaignRun> runs = db->list_runs();
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].id, run);
  EXPECT_EQ(runs[0].ego_version, "abc123");
  EXPECT_EQ(runs[0].started.size(), 20u) << runs[0].started;  // 2026-11-27T02:00:00Z
  EXPECT_FALSE(runs[0].ended.empty());
  ASSERT_EQ(db->list_seeds().size(), 1u);
  EXPECT_EQ(db->list_seeds()[0].path, "corpus/a.avu");
  ASSERT_EQ(db->list_failure_modes().size(), 1u);
  EXPECT_EQ(db->list_failure_modes()[0].record.signature, "collision|npc1|ego");
  // A second run gets the next id.
  EXPECT_EQ(db->begin_run("abc124"), run + 1);
  EXPECT_TRUE(db->list_runs()[1].ended.empty());
}

TEST_F(CampaignDbTest, AnEditedSeedIsANewSeed) {
  auto db = open();
  ASSERT_TRUE(db);
  fs::create_directories(dir_ / "corpus");
  const fs::path file = dir_ / "corpus" / "a.avu";
  std::ofstream(file) << "scenario a { }\n";
  const std::int64_t first = db->upsert_seed("corpus/a.avu", *file_content_hash(file));
  EXPECT_EQ(db->upsert_seed("corpus/a.avu", *file_content_hash(file)), first);
  std::ofstream(file) << "scenario a { } // edited\n";
  const std::int64_t edited = db->upsert_seed("corpus/a.avu", *file_content_hash(file));
  EXPECT_NE(edited, first);
  // The same bytes under another path are another seed too.
  const std::int64_t copy = db->upsert_seed("corpus/b.avu", *file_content_hash(file));
  EXPECT_NE(copy, edited);
  const std::vector<CampaignSeed> seeds = db->list_seeds();
  ASSERT_EQ(seeds.size(), 3u);
  EXPECT_NE(seeds[0].content_hash, seeds[1].content_hash);
  EXPECT_EQ(seeds[1].content_hash, seeds[2].content_hash);
}

TEST_F(CampaignDbTest, ContentHashIsFnv1a64) {
  // The published FNV-1a test vectors: the names in a database must never change.
  EXPECT_EQ(content_hash(""), "cbf29ce484222325");
  EXPECT_EQ(content_hash("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(content_hash("foobar"), "85944171f73967e8");
  EXPECT_FALSE(file_content_hash(dir_ / "no such file"));
}

TEST_F(CampaignDbTest, FailureModesRecordFirstAndLastSeenAndStatus) {
  auto db = open();
  ASSERT_TRUE(db);
  const std::int64_t seed = db->upsert_seed("a.avu", content_hash("a"));
  const std::int64_t run1 = db->begin_run("v1");
  CampaignFailureMode found = db->upsert_failure_mode(run1, mode(seed, "sig"));
  EXPECT_EQ(found.status, FailureModeStatus::new_mode);
  EXPECT_EQ(found.first_seen_run, run1);
  EXPECT_EQ(found.last_seen_run, run1);
  // Found again in the run that found it: still new.
  EXPECT_EQ(db->upsert_failure_mode(run1, mode(seed, "sig")).status, FailureModeStatus::new_mode);

  const std::int64_t run2 = db->begin_run("v2");
  FailureModeRecord again = mode(seed, "sig");
  again.scenario_file = "fedcba9876543210.avu";
  found = db->upsert_failure_mode(run2, again);
  EXPECT_EQ(found.status, FailureModeStatus::still_failing);
  EXPECT_EQ(found.first_seen_run, run1);
  EXPECT_EQ(found.last_seen_run, run2);
  // The representative stays the first one found.
  EXPECT_EQ(found.record.scenario_file, "0123456789abcdef.avu");

  db->set_failure_mode_status(found.id, FailureModeStatus::fixed);
  const std::int64_t run3 = db->begin_run("v3");
  EXPECT_EQ(db->upsert_failure_mode(run3, mode(seed, "sig")).status, FailureModeStatus::regressed);
  EXPECT_EQ(db->upsert_failure_mode(run3, mode(seed, "sig")).status, FailureModeStatus::regressed);
  const std::int64_t run4 = db->begin_run("v4");
  EXPECT_EQ(db->upsert_failure_mode(run4, mode(seed, "sig")).status,
            FailureModeStatus::still_failing);

  // The same signature on another seed is another failure mode.
  const std::int64_t other_seed = db->upsert_seed("b.avu", content_hash("b"));
  EXPECT_EQ(db->upsert_failure_mode(run4, mode(other_seed, "sig")).status,
            FailureModeStatus::new_mode);
  const std::vector<CampaignFailureMode> modes = db->list_failure_modes();
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_EQ(modes[0].record.seed_id, seed);
  EXPECT_EQ(modes[0].first_seen_run, run1);
  EXPECT_EQ(modes[0].last_seen_run, run4);
  EXPECT_EQ(modes[1].record.seed_id, other_seed);
  EXPECT_THROW(db->set_failure_mode_status(999, FailureModeStatus::fixed), CampaignDbError);
}

TEST_F(CampaignDbTest, RecordsASearchWithItsEvaluations) {
  auto db = open();
  ASSERT_TRUE(db);
  const std::int64_t run = db->begin_run("v1");
  const std::int64_t seed = db->upsert_seed("a.avu", content_hash("a"));
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<CampaignEvaluation> evaluations = {
      {0, 1.5, false}, {1, std::nullopt, false}, {2, -0.25, true}, {3, inf, false}};
  const std::int64_t search =
      db->record_search(search_record(run, seed, 4, "searches/1"), evaluations);
  const std::vector<CampaignSearch> searches = db->list_searches();
  ASSERT_EQ(searches.size(), 1u);
  EXPECT_EQ(searches[0].id, search);
  EXPECT_EQ(searches[0].record.algorithm, "ga");
  EXPECT_EQ(searches[0].record.budget, 4u);
  EXPECT_EQ(searches[0].record.status, SearchStatus::done);
  EXPECT_EQ(searches[0].record.output_folder, "searches/1");
  const std::vector<CampaignEvaluation> stored = db->list_evaluations(search);
  ASSERT_EQ(stored.size(), 4u);
  EXPECT_EQ(stored[0].robustness, 1.5);
  EXPECT_FALSE(stored[1].robustness);
  EXPECT_EQ(stored[2].robustness, -0.25);
  EXPECT_TRUE(stored[2].finding);
  EXPECT_EQ(stored[3].robustness, inf);
}

// A failure half-way through a state change leaves none of its rows.
TEST_F(CampaignDbTest, AFailedChangeLeavesNoPartialRows) {
  auto db = open();
  ASSERT_TRUE(db);
  const std::int64_t run = db->begin_run("v1");
  const std::int64_t seed = db->upsert_seed("a.avu", content_hash("a"));
  // The search row and two evaluations go in before the duplicate index fails.
  const std::vector<CampaignEvaluation> duplicate = {
      {0, 1.0, false}, {1, 2.0, false}, {1, 3.0, false}};
  EXPECT_THROW(db->record_search(search_record(run, seed, 3, "s"), duplicate), CampaignDbError);
  EXPECT_TRUE(db->list_searches().empty());
  EXPECT_TRUE(db->list_evaluations(1).empty());
  // A search of a seed that does not exist breaks a foreign key.
  EXPECT_THROW(db->record_search(search_record(run, seed + 100, 1, "s"),
                                 std::vector<CampaignEvaluation>{{0, 1.0, false}}),
               CampaignDbError);
  EXPECT_TRUE(db->list_searches().empty());
  EXPECT_THROW(db->upsert_failure_mode(run + 100, mode(seed, "sig")), CampaignDbError);
  EXPECT_TRUE(db->list_failure_modes().empty());
  // The connection is still usable afterwards.
  const std::int64_t search = db->record_search(search_record(run, seed, 1, "s"),
                                                std::vector<CampaignEvaluation>{{0, 1.0, false}});
  EXPECT_EQ(db->list_searches().size(), 1u);
  EXPECT_EQ(db->list_evaluations(search).size(), 1u);
}

// A campaign search's result goes in whole: its row, evaluations and modes, with the modes its
// seed did not know counted; a search recorded twice (same run, round, seed and spec) is refused
// and leaves no second set of modes behind.
TEST_F(CampaignDbTest, RecordsASearchResultWithItsModesInOneTransaction) {
  auto db = open();
  ASSERT_TRUE(db);
  const std::int64_t run = db->begin_run("v1");
  const std::int64_t seed = db->upsert_seed("a.avu", content_hash("a"));
  db->upsert_failure_mode(run, mode(seed, "known"));
  SearchRecord search = search_record(run, seed, 2, "searches/run-1/round-0/1-0");
  search.spec_index = 1;
  search.search_seed = 0xfedcba9876543210u;  // above 2^63: stored by its bits
  search.simulations = 2;
  search.best_robustness = -0.5;
  const std::vector<CampaignEvaluation> evaluations = {{0, 0.5, false}, {1, -0.5, true}};
  const std::vector<FailureModeRecord> modes = {mode(seed, "known"), mode(seed, "fresh")};
  const std::vector<std::string> coverage = {"light.day", "ego.following", "weather.clear"};
  const RecordedSearch recorded = db->record_search_result(search, evaluations, modes, coverage);
  EXPECT_EQ(recorded.new_modes, 1);
  EXPECT_EQ(db->list_coverage(recorded.search_id),
            (std::vector<std::string>{"ego.following", "light.day", "weather.clear"}));
  ASSERT_EQ(db->list_searches().size(), 1u);
  const SearchRecord stored = db->list_searches()[0].record;
  EXPECT_EQ(stored.new_modes, 1);
  EXPECT_EQ(stored.spec_index, 1);
  EXPECT_EQ(stored.spec, "spec1");
  EXPECT_EQ(stored.search_seed, 0xfedcba9876543210u);
  EXPECT_EQ(stored.simulations, 2u);
  EXPECT_EQ(stored.best_robustness, -0.5);
  EXPECT_EQ(db->list_evaluations(recorded.search_id).size(), 2u);
  ASSERT_EQ(db->list_failure_modes().size(), 2u);

  const std::vector<FailureModeRecord> more = {mode(seed, "another")};
  const std::vector<std::string> other = {"road.merge"};
  EXPECT_THROW(db->record_search_result(search, evaluations, more, other), CampaignDbError);
  EXPECT_EQ(db->list_failure_modes().size(), 2u);
  EXPECT_EQ(db->list_coverage(recorded.search_id).size(), 3u);
  EXPECT_EQ(db->list_searches().size(), 1u);
}

TEST_F(CampaignDbTest, ReplayVerdictsMoveStatuses) {
  using S = FailureModeStatus;
  EXPECT_EQ(replay_verdict(S::new_mode, {4, 4, ""}).status, S::still_failing);
  EXPECT_EQ(replay_verdict(S::fixed, {4, 4, ""}).status, S::regressed);
  EXPECT_EQ(replay_verdict(S::fixed, {4, 4, ""}).verdict, "regressed");
  EXPECT_EQ(replay_verdict(S::still_failing, {4, 0, ""}).status, S::fixed);
  EXPECT_EQ(replay_verdict(S::still_failing, {4, 1, ""}).status, S::flaky);
  EXPECT_EQ(replay_verdict(S::flaky, {0, 0, ""}).status, S::flaky);
  EXPECT_EQ(replay_verdict(S::flaky, {0, 0, ""}).verdict, "not_replayed");
  EXPECT_EQ(replay_verdict(S::new_mode, {4, 2, "gone"}).status, S::new_mode);
  EXPECT_EQ(replay_verdict(S::new_mode, {4, 2, "gone"}).verdict, "error");
}

TEST_F(CampaignDbTest, RecordsOneReplayPerModeAndRun) {
  auto db = open();
  ASSERT_TRUE(db);
  const std::int64_t first = db->begin_run("v1");
  const std::int64_t seed = db->upsert_seed("a.avu", content_hash("a"));
  const std::int64_t id = db->upsert_failure_mode(first, mode(seed, "sig")).id;
  db->end_run(first);
  const std::int64_t second = db->begin_run("v2");
  EXPECT_EQ(db->unfinished_run()->id, second);
  const CampaignReplay replay = db->record_replay(second, id, {3, 0, ""});
  EXPECT_EQ(replay.verdict, "fixed");
  EXPECT_EQ(db->list_failure_modes()[0].status, FailureModeStatus::fixed);
  EXPECT_THROW(db->record_replay(second, id, {3, 3, ""}), CampaignDbError);
  EXPECT_EQ(db->list_failure_modes()[0].status, FailureModeStatus::fixed);
  ASSERT_EQ(db->list_replays().size(), 1u);
  EXPECT_EQ(db->list_replays()[0].tried, 3);
  EXPECT_THROW(db->record_replay(second, id + 7, {3, 3, ""}), CampaignDbError);
  db->end_run(second);
  EXPECT_FALSE(db->unfinished_run());
}

// A fix that the replay found broken (regressed) stays regressed when a search of the same run
// finds the mode too: the search confirms the regression, it does not make it "still failing".
TEST_F(CampaignDbTest, AModeTheReplayFoundRegressedStaysRegressedWhenASearchFindsIt) {
  auto db = open();
  ASSERT_TRUE(db);
  const std::int64_t first = db->begin_run("v1");
  const std::int64_t seed = db->upsert_seed("a.avu", content_hash("a"));
  const std::int64_t id = db->upsert_failure_mode(first, mode(seed, "sig")).id;
  db->end_run(first);
  const std::int64_t second = db->begin_run("v2");
  db->record_replay(second, id, {3, 0, ""});  // fixed
  db->end_run(second);
  const std::int64_t third = db->begin_run("v1");
  EXPECT_EQ(db->record_replay(third, id, {3, 3, ""}).verdict, "regressed");
  const std::vector<FailureModeRecord> found = {mode(seed, "sig")};
  db->record_search_result(search_record(third, seed, 32, "s3"), {}, found);
  EXPECT_EQ(db->list_failure_modes()[0].status, FailureModeStatus::regressed);
  EXPECT_EQ(db->list_failure_modes()[0].last_seen_run, third);
}

// Each search records which modes it found (the report's "found in run R"), new or not, and a
// replay keeps its error.
TEST_F(CampaignDbTest, RecordsSightingsAndReplayErrors) {
  auto db = open();
  ASSERT_TRUE(db);
  const std::int64_t first = db->begin_run("v1");
  const std::int64_t seed = db->upsert_seed("a.avu", content_hash("a"));
  const std::vector<FailureModeRecord> both = {mode(seed, "a"), mode(seed, "b")};
  const std::int64_t s1 =
      db->record_search_result(search_record(first, seed, 32, "s1"), {}, both).search_id;
  db->end_run(first);
  const std::int64_t second = db->begin_run("v1");
  const std::int64_t a = db->list_failure_modes()[0].id;
  const std::int64_t b = db->list_failure_modes()[1].id;
  db->record_replay(second, b, {0, 0, "modes/x.avu: cannot read"});
  const std::vector<FailureModeRecord> one = {mode(seed, "a")};
  const std::int64_t s2 =
      db->record_search_result(search_record(second, seed, 32, "s2"), {}, one).search_id;
  const std::vector<CampaignSighting> sightings = db->list_sightings();
  ASSERT_EQ(sightings.size(), 3u);
  EXPECT_EQ(sightings[0].run_id, first);
  EXPECT_EQ(sightings[0].failure_mode_id, a);
  EXPECT_EQ(sightings[0].search_id, s1);
  EXPECT_EQ(sightings[1].failure_mode_id, b);
  EXPECT_EQ(sightings[2].run_id, second);
  EXPECT_EQ(sightings[2].failure_mode_id, a);
  EXPECT_EQ(sightings[2].search_id, s2);
  ASSERT_EQ(db->list_replays().size(), 1u);
  EXPECT_EQ(db->list_replays()[0].verdict, "error");
  EXPECT_EQ(db->list_replays()[0].error, "modes/x.avu: cannot read");
}

TEST_F(CampaignDbTest, RefusesAnOlderSchemaSayingWhatToDo) {
  {
    auto db = open();
    ASSERT_TRUE(db);
  }
  sqlite_set_version(dir_ / "campaign.db", 1);
  const CampaignDbOpening opening = CampaignDb::open(dir_);
  EXPECT_FALSE(opening.db);
  EXPECT_NE(opening.error.find("its schema version is 1, this scenfuzz reads version 3"),
            std::string::npos)
      << opening.error;
  EXPECT_NE(opening.error.find("move campaign.db away"), std::string::npos) << opening.error;
}

// A database of schema 2 (before coverage) is migrated when a run opens it: its searches keep
// everything and have no coverage; later searches record theirs. A report reads it unmigrated.
TEST_F(CampaignDbTest, MigratesSchemaTwoByAddingTheCoverageTable) {
  std::int64_t old_search = 0;
  {
    auto db = open();
    ASSERT_TRUE(db);
    const std::int64_t run = db->begin_run("v1");
    const std::int64_t seed = db->upsert_seed("a.avu", content_hash("a"));
    old_search = db->record_search(search_record(run, seed, 1, "s"),
                                   std::vector<CampaignEvaluation>{{0, 1.0, false}});
  }
  sqlite3* connection = nullptr;
  ASSERT_EQ(sqlite3_open((dir_ / "campaign.db").c_str(), &connection), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(connection, "DROP TABLE coverage", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(connection);
  sqlite_set_version(dir_ / "campaign.db", 2);
  {
    const CampaignDbOpening reading = CampaignDb::open_for_reading(dir_);
    ASSERT_TRUE(reading.db) << reading.error;
    EXPECT_EQ(reading.db->schema_version(), 2);
    EXPECT_TRUE(reading.db->list_coverage(old_search).empty());
  }
  auto db = open();
  ASSERT_TRUE(db);
  EXPECT_EQ(db->schema_version(), 3);
  ASSERT_EQ(db->list_searches().size(), 1u);
  EXPECT_EQ(db->list_evaluations(old_search).size(), 1u);
  EXPECT_TRUE(db->list_coverage(old_search).empty());
  SearchRecord search = search_record(1, 1, 1, "t", 1);
  const std::vector<std::string> coverage = {"ego.following"};
  const RecordedSearch recorded = db->record_search_result(
      search, std::vector<CampaignEvaluation>{{0, 2.0, false}}, {}, coverage);
  EXPECT_EQ(db->list_coverage(recorded.search_id), coverage);
}

TEST_F(CampaignDbTest, ASecondOpenerIsRefusedNamingTheFirst) {
  auto first = open();
  ASSERT_TRUE(first);
  const CampaignDbOpening second = CampaignDb::open(dir_);
  EXPECT_FALSE(second.db);
  EXPECT_NE(second.error.find("the campaign '" + dir_.string() + "' is in use by another run"),
            std::string::npos)
      << second.error;
  EXPECT_NE(second.error.find("process " + std::to_string(::getpid()) + " on "), std::string::npos)
      << second.error;
  // Once the first closes, the campaign can be opened again.
  first.reset();
  EXPECT_TRUE(open());
}

TEST_F(CampaignDbTest, AnotherProcessIsRefusedToo) {
  auto first = open();
  ASSERT_TRUE(first);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const CampaignDbOpening second = CampaignDb::open(dir_);
    const bool refused =
        !second.db &&
        second.error.find("process " + std::to_string(::getppid())) != std::string::npos;
    ::_exit(refused ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST_F(CampaignDbTest, RefusesAFileThatIsNotACampaignDatabase) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "campaign.db") << "this is not a database, only some text in its place\n";
  const CampaignDbOpening opening = CampaignDb::open(dir_);
  EXPECT_FALSE(opening.db);
  EXPECT_NE(opening.error.find("cannot use '" + (dir_ / "campaign.db").string() + "': "),
            std::string::npos)
      << opening.error;
  EXPECT_NE(opening.error.find("not a database"), std::string::npos) << opening.error;
}

}  // namespace
}  // namespace scenfuzz
