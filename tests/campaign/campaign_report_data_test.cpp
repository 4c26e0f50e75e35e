// The report's data, from a campaign database built through its API: per seed the best
// robustness so far across its searches in order, per run the modes new, failing, fixed,
// regressed and flaky (exactly, from the replays and the searches' sightings), pictures found
// beside the scenarios.
#include "fuzz/campaign/campaign_report_data.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/content_hash.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

TEST(BestSoFarTest, OnePointPerImprovementCountingUnjudgedSimulations) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(best_so_far({}).empty());
  EXPECT_TRUE(best_so_far({std::nullopt, std::nullopt}).empty());
  EXPECT_EQ(best_so_far({std::nullopt, inf, 3.0, 4.0, std::nullopt, 3.0, -1.0, -inf, 0.0}),
            (std::vector<BestSoFar>{{2, inf}, {3, 3.0}, {7, -1.0}, {8, -inf}}));
}

class CampaignReportDataTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scenfuzz_report_data_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    CampaignDbOpening opening = CampaignDb::open(dir_);
    ASSERT_TRUE(opening.db) << opening.error;
    db_ = std::move(opening.db);
  }
  void TearDown() override {
    db_.reset();
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  std::int64_t search(std::int64_t run, std::int64_t seed,
                      const std::vector<std::optional<double>>& robustness,
                      const std::vector<std::string>& found_modes = {},
                      const std::vector<std::string>& coverage = {}) {
    std::vector<CampaignEvaluation> evaluations;
    for (std::size_t i = 0; i < robustness.size(); ++i)
      evaluations.push_back(
          {static_cast<std::int64_t>(i), robustness[i], robustness[i] && *robustness[i] < 0});
    SearchRecord search;
    search.run_id = run;
    search.seed_id = seed;
    search.algorithm = "ga";
    search.budget = robustness.size();
    search.output_folder = "s";
    std::vector<FailureModeRecord> modes;
    for (const std::string& signature : found_modes) modes.push_back(record(seed, signature));
    return db_->record_search_result(search, evaluations, modes, coverage).search_id;
  }

  static FailureModeRecord record(std::int64_t seed, const std::string& signature) {
    return {seed, signature, "spec1", "ego", "modes/" + signature + ".avu", "replay " + signature};
  }

  CampaignFailureMode found(std::int64_t run, std::int64_t seed, const std::string& signature) {
    return db_->upsert_failure_mode(run, record(seed, signature));
  }

  fs::path dir_;
  std::unique_ptr<CampaignDb> db_;
};

TEST_F(CampaignReportDataTest, SeedsRunsAndFailureModes) {
  const std::int64_t run1 = db_->begin_run("v1");
  const std::int64_t a = db_->upsert_seed("a.avu", content_hash("a"));
  const std::int64_t b = db_->upsert_seed("b.avu", content_hash("b"));
  search(run1, a, {3.0, std::nullopt, 2.0, 5.0, -1.0}, {"m1", "m2", "m3"},
         {"ego.following", "light.day"});
  const std::vector<CampaignFailureMode> first = db_->list_failure_modes();
  ASSERT_EQ(first.size(), 3u);
  const std::int64_t m1 = first[0].id, m2 = first[1].id, m3 = first[2].id;
  db_->end_run(run1);

  // Run 2: m1 and m3 fixed by the replay; m2's replay fails (it is not failing in run 2, though
  // it was first seen before and last seen after); m5 new.
  const std::int64_t run2 = db_->begin_run("v2");
  db_->record_replay(run2, m1, {3, 0, ""});
  db_->record_replay(run2, m2, {0, 0, "modes/m2.avu: cannot read"});
  db_->record_replay(run2, m3, {3, 0, ""});
  search(run2, a, {0.5, -2.0}, {}, {"light.day", "road.merge"});
  const std::int64_t m5 = found(run2, b, "m5").id;
  db_->end_run(run2);

  // Run 3: m1 fixed by the replay, then found again by a search: regressed. m2 still failing; m3
  // fixed again; m5 flaky; m4 new.
  const std::int64_t run3 = db_->begin_run("v2");
  db_->record_replay(run3, m1, {3, 0, ""});
  db_->record_replay(run3, m2, {3, 3, ""});
  db_->record_replay(run3, m3, {3, 0, ""});
  db_->record_replay(run3, m5, {3, 1, ""});
  found(run3, a, "m1");
  found(run3, a, "m2");
  found(run3, b, "m4");

  // m1 has a picture beside its scenario; the others do not.
  fs::create_directories(dir_ / "modes");
  std::ofstream(dir_ / "modes" / "m1.svg") << "<svg xmlns=\"http://www.w3.org/2000/svg\"/>";

  const ReportData data = load_report_data(*db_, dir_, "nightly");
  EXPECT_EQ(data.name, "nightly");

  ASSERT_EQ(data.seeds.size(), 2u);
  const ReportSeed& seed_a = data.seeds[0];
  EXPECT_EQ(seed_a.seed.path, "a.avu");
  EXPECT_EQ(seed_a.searches, 2u);
  EXPECT_EQ(seed_a.simulations, 7u);
  EXPECT_EQ(seed_a.judged, 6u);
  EXPECT_EQ(seed_a.best, (std::vector<BestSoFar>{{1, 3.0}, {3, 2.0}, {5, -1.0}, {7, -2.0}}));
  ASSERT_EQ(seed_a.run_starts.size(), 2u);
  EXPECT_EQ(seed_a.run_starts[0].run_id, run1);
  EXPECT_EQ(seed_a.run_starts[0].simulations, 0u);
  EXPECT_EQ(seed_a.run_starts[1].run_id, run2);
  EXPECT_EQ(seed_a.run_starts[1].simulations, 5u);
  EXPECT_EQ(seed_a.failure_modes, 3u);
  // Its searches' features counted once: ego.following, light.day, road.merge.
  EXPECT_EQ(seed_a.features, 3u);
  EXPECT_EQ(data.seeds[1].features, 0u);
  EXPECT_EQ(data.corpus_features, 3u);
  EXPECT_EQ(data.seeds[1].searches, 0u);
  EXPECT_TRUE(data.seeds[1].best.empty());
  EXPECT_EQ(data.seeds[1].failure_modes, 2u);

  ASSERT_EQ(data.runs.size(), 3u);
  const ReportRun& r1 = data.runs[0];
  const ReportRun& r2 = data.runs[1];
  const ReportRun& r3 = data.runs[2];
  EXPECT_EQ(r1.run.ego_version, "v1");
  EXPECT_FALSE(r1.run.ended.empty());
  EXPECT_TRUE(r3.run.ended.empty());
  // searches, simulations, new, failing, fixed, regressed, flaky.
  const auto counts = [](const ReportRun& r) {
    return std::vector<std::size_t>({r.searches, r.simulations, r.modes_first_seen, r.modes_seen,
                                     r.fixed, r.regressed, r.flaky});
  };
  EXPECT_EQ(counts(r1), std::vector<std::size_t>({1, 5, 3, 3, 0, 0, 0}));
  EXPECT_EQ(counts(r2), std::vector<std::size_t>({1, 2, 1, 1, 2, 0, 0}));
  EXPECT_EQ(counts(r3), std::vector<std::size_t>({0, 0, 1, 3, 1, 1, 1}));

  ASSERT_EQ(data.failure_modes.size(), 5u);
  const ReportFailureMode& shown_m1 = data.failure_modes[0];
  EXPECT_EQ(shown_m1.mode.status, FailureModeStatus::regressed);
  EXPECT_EQ(shown_m1.seed_path, "a.avu");
  EXPECT_EQ(shown_m1.picture, "modes/m1.svg");
  EXPECT_EQ(shown_m1.first_seen_started, r1.run.started);
  EXPECT_EQ(shown_m1.last_seen_started, r3.run.started);
  EXPECT_EQ(data.failure_modes[1].mode.status, FailureModeStatus::still_failing);
  EXPECT_EQ(data.failure_modes[1].picture, "");
  EXPECT_EQ(data.failure_modes[2].mode.status, FailureModeStatus::fixed);
  EXPECT_EQ(data.failure_modes[3].mode.status, FailureModeStatus::flaky);
  EXPECT_EQ(data.failure_modes[3].seed_path, "b.avu");
  EXPECT_EQ(data.failure_modes[4].mode.status, FailureModeStatus::new_mode);
}

TEST_F(CampaignReportDataTest, AnEmptyCampaignHasNothingToShow) {
  const ReportData data = load_report_data(*db_, dir_, "empty");
  EXPECT_TRUE(data.runs.empty());
  EXPECT_TRUE(data.seeds.empty());
  EXPECT_TRUE(data.failure_modes.empty());
}

}  // namespace
}  // namespace scenfuzz
