// CampaignDb::open_for_reading, the report's way in: it reads a campaign while a run holds the
// lock and writes, sees each committed change, never creates or changes a database, and refuses
// what is not a campaign's database with the reason.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz/campaign/campaign_db.hpp"
#include "fuzz/content_hash.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

class CampaignDbReadingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scenfuzz_campaign_db_reading_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  fs::path dir_;
};

TEST_F(CampaignDbReadingTest, ReadsWhileARunHoldsTheLockAndSeesItsCommits) {
  CampaignDbOpening run = CampaignDb::open(dir_);
  ASSERT_TRUE(run.db) << run.error;
  const std::int64_t run_id = run.db->begin_run("v1");
  const std::int64_t seed = run.db->upsert_seed("a.avu", content_hash("a"));

  CampaignDbOpening reader = CampaignDb::open_for_reading(dir_);
  ASSERT_TRUE(reader.db) << reader.error;
  EXPECT_EQ(reader.db->list_runs().size(), 1u);
  EXPECT_EQ(reader.db->list_seeds().size(), 1u);

  // The run goes on writing while the reader is open; the reader's next query sees it.
  const CampaignEvaluation evaluations[] = {{0, -0.5, true}, {1, 2.0, false}};
  SearchRecord search;
  search.run_id = run_id;
  search.seed_id = seed;
  search.algorithm = "ga";
  search.budget = 2;
  search.output_folder = "searches/x";
  run.db->record_search(search, evaluations);
  run.db->upsert_failure_mode(run_id, {seed, "sig", "spec1", "ego", "modes/h.avu", "replay"});
  ASSERT_EQ(reader.db->list_searches().size(), 1u);
  EXPECT_EQ(reader.db->list_evaluations(reader.db->list_searches()[0].id).size(), 2u);
  EXPECT_EQ(reader.db->list_failure_modes().size(), 1u);

  // The lock is still the run's: a second run is refused while the reader is open.
  EXPECT_FALSE(CampaignDb::open(dir_).db);
}

TEST_F(CampaignDbReadingTest, WritesThroughAReaderFailWithoutChangingTheDatabase) {
  { ASSERT_TRUE(CampaignDb::open(dir_).db); }
  CampaignDbOpening reader = CampaignDb::open_for_reading(dir_);
  ASSERT_TRUE(reader.db) << reader.error;
  EXPECT_THROW(reader.db->begin_run("v1"), CampaignDbError);
  EXPECT_TRUE(reader.db->list_runs().empty());
}

TEST_F(CampaignDbReadingTest, AFolderWithoutADatabaseIsRefusedAndLeftAsItWas) {
  const CampaignDbOpening reader = CampaignDb::open_for_reading(dir_);
  EXPECT_FALSE(reader.db);
  EXPECT_EQ(reader.error,
            "'" + dir_.string() + "' is not a campaign folder: it has no campaign.db");
  EXPECT_TRUE(fs::is_empty(dir_));  // neither a database nor a lock file was created
}

TEST_F(CampaignDbReadingTest, WhatIsNotACampaignDatabaseIsRefusedWithTheReason) {
  std::ofstream(dir_ / "campaign.db") << "not a database at all, just text\n";
  const CampaignDbOpening junk = CampaignDb::open_for_reading(dir_);
  EXPECT_FALSE(junk.db);
  EXPECT_NE(junk.error.find("file is not a database"), std::string::npos) << junk.error;
  EXPECT_NE(junk.error.find((dir_ / "campaign.db").string()), std::string::npos) << junk.error;
}

TEST_F(CampaignDbReadingTest, AnEmptySqliteFileIsNotACampaignsAndStaysEmpty) {
  std::ofstream(dir_ / "campaign.db").flush();  // SQLite takes an empty file as an empty database
  const CampaignDbOpening empty = CampaignDb::open_for_reading(dir_);
  EXPECT_FALSE(empty.db);
  EXPECT_NE(empty.error.find("not a campaign's"), std::string::npos) << empty.error;
  EXPECT_EQ(fs::file_size(dir_ / "campaign.db"), 0u);
}

}  // namespace
}  // namespace scenfuzz
