// The search's law coverage (docs/coverage.md, "Law coverage"): summary.json's k of N with the
// reached sub-violations, their formulas and the first evaluation of each; --target
// sub-violations, which drops a target once its sub-violation is reached and reaches more of a
// law's sub-violations than the search for its violation; the same journal for -j 1 and -j 2,
// and after a resume. tests/fuzz/data/law/speed_bands.scenest: four narrow bands of start speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "command_runner.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using test::slurp;

const std::string kBands = test::source_file("tests/fuzz/data/law/speed_bands.scenest");

nlohmann::json law_coverage_of(const fs::path& out) {
  return nlohmann::json::parse(slurp(out / "summary.json")).at("law_coverage");
}

std::set<std::string> reached_names(const nlohmann::json& law) {
  std::set<std::string> names;
  for (const nlohmann::json& spec : law)
    for (const nlohmann::json& sub : spec.at("reached")) names.insert(sub.at("name"));
  return names;
}

std::size_t column_of(const std::vector<std::string>& header, const std::string& name) {
  const auto found = std::find(header.begin(), header.end(), name);
  EXPECT_NE(found, header.end()) << name;
  return static_cast<std::size_t>(found - header.begin());
}

// The journal without its wall_seconds column (the one thing that differs between runs).
std::vector<std::vector<std::string>> journal_of(const fs::path& out) {
  std::vector<std::vector<std::string>> rows = test::read_csv(slurp(out / "evaluations.csv"));
  const std::size_t wall = column_of(rows.front(), "wall_seconds");
  for (auto& row : rows)
    if (row.size() > wall) row.erase(row.begin() + static_cast<std::ptrdiff_t>(wall));
  return rows;
}

class LawCoverageSearchTest : public test::CommandTest {
 protected:
  std::vector<std::string> args(const fs::path& out, const std::string& jobs,
                                const std::string& target) {
    return {"--budget", "60",    "--seed",     "3",        "-j",   jobs,
            "--quiet",  "--out", out.string(), "--target", target, kBands};
  }
};

TEST_F(LawCoverageSearchTest, TheSummaryReportsKOfNWithTheReachedSubViolations) {
  const fs::path out = dir_ / "plain";
  std::vector<std::string> plain = args(out, "1", "specs");
  plain.erase(std::find(plain.begin(), plain.end(), "--quiet"));
  const test::Outcome outcome = scenfuzz(plain);
  ASSERT_TRUE(outcome.exit_code == 0 || outcome.exit_code == 1) << outcome.err;
  const nlohmann::json law = law_coverage_of(out);
  ASSERT_EQ(law.size(), 1u) << law.dump();
  const nlohmann::json& spec = law[0];
  EXPECT_EQ(spec.at("spec"), "bands");
  EXPECT_EQ(spec.at("of"), 4);
  const std::size_t covered = spec.at("covered");
  EXPECT_GE(covered, 1u) << spec.dump();
  EXPECT_EQ(spec.at("reached").size(), covered);
  EXPECT_EQ(spec.at("unreached").size(), 4 - covered);
  for (const nlohmann::json& sub : spec.at("reached")) {
    // The formula as AVUnit: a band of the speed, "speed > 20 & ~(speed > 21)" for band 2.
    EXPECT_NE(sub.at("formula").get<std::string>().find("speed >"), std::string::npos) << sub;
    EXPECT_LT(sub.at("first_evaluation").get<std::size_t>(), 60u);
  }
  // The same sub-violations as the coverage's law family, which the journal's rows carry.
  std::set<std::string> law_features;
  for (const std::string& name : nlohmann::json::parse(slurp(out / "summary.json"))
                                     .at("coverage")
                                     .at("names")
                                     .get<std::vector<std::string>>())
    if (name.rfind("law.", 0) == 0) law_features.insert(name);
  EXPECT_EQ(reached_names(law), law_features);
  // And the end-of-search text says so.
  EXPECT_NE(outcome.out.find("law coverage of bands: " + std::to_string(covered) +
                             " of 4 sub-violations"),
            std::string::npos)
      << outcome.out;
}

// The bands are 2 % of the speed range each: the search for the law's violation settles on one,
// one target per band reaches them all (fixed seed, so deterministic). The law reads only t = 0,
// the start state: its violations are start-state, not findings (exit 0), but its sub-violations
// are reached all the same.
TEST_F(LawCoverageSearchTest, TargetingSubViolationsReachesMoreAndDropsTheReachedOnes) {
  const fs::path plain = dir_ / "plain", targeted = dir_ / "targeted";
  ASSERT_EQ(scenfuzz(args(plain, "1", "specs")).exit_code, 0);
  ASSERT_EQ(scenfuzz(args(targeted, "1", "sub-violations")).exit_code, 0);
  const std::size_t by_spec = law_coverage_of(plain)[0].at("covered");
  const std::size_t by_sub = law_coverage_of(targeted)[0].at("covered");
  EXPECT_GT(by_sub, by_spec);
  EXPECT_EQ(by_sub, 4u);

  // No batch of a sub-violation's target starts after an evaluation reached it: the journal's
  // batches are runs of one target, and each target's coverage feature is its name.
  const auto rows = journal_of(targeted);
  const std::size_t target = column_of(rows.front(), "target");
  const std::size_t coverage = column_of(rows.front(), "coverage");
  std::set<std::string> reached, targets;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const std::string& name = rows[r].at(target);
    targets.insert(name);
    const bool batch_start = r == 1 || rows[r - 1].at(target) != name;
    if (batch_start) {
      EXPECT_EQ(reached.count(name), 0u) << "row " << r << " targets " << name;
    }
    const std::string& features = rows[r].at(coverage);
    for (int k = 1; k <= 4; ++k)
      if (features.find("law.bands." + std::to_string(k)) != std::string::npos)
        reached.insert("law.bands." + std::to_string(k));
  }
  // Once all four are reached, the rest of the budget searches the law itself.
  EXPECT_EQ(targets, (std::set<std::string>{"bands", "law.bands.1", "law.bands.2", "law.bands.3",
                                            "law.bands.4"}));
  std::set<std::string> before;
  for (std::size_t r = 1; r < rows.size() && rows[r].at(target) != "bands"; ++r)
    for (int k = 1; k <= 4; ++k)
      if (rows[r].at(coverage).find("law.bands." + std::to_string(k)) != std::string::npos)
        before.insert("law.bands." + std::to_string(k));
  EXPECT_EQ(before.size(), 4u) << "the law's own target starts once every band is reached";
}

TEST_F(LawCoverageSearchTest, TargetingGivesTheSameSearchForAnyNumberOfJobs) {
  ASSERT_EQ(scenfuzz(args(dir_ / "one", "1", "sub-violations")).exit_code, 0);
  ASSERT_EQ(scenfuzz(args(dir_ / "two", "2", "sub-violations")).exit_code, 0);
  EXPECT_EQ(journal_of(dir_ / "one"), journal_of(dir_ / "two"));
  EXPECT_EQ(law_coverage_of(dir_ / "one"), law_coverage_of(dir_ / "two"));
}

// A kill leaves a prefix of the journal: the replayed evaluations tell the targets what they
// were told (their sub-violations' robustness), so the search goes on as the uninterrupted one.
TEST_F(LawCoverageSearchTest, AResumedTargetingSearchEqualsAnUninterruptedOne) {
  const fs::path reference = dir_ / "reference", out = dir_ / "killed";
  ASSERT_EQ(scenfuzz(args(reference, "2", "sub-violations")).exit_code, 0);
  ASSERT_EQ(scenfuzz(args(out, "1", "sub-violations")).exit_code, 0);
  const std::string journal = slurp(out / "evaluations.csv");
  std::size_t cut = 0;
  for (int line = 0; line < 1 + 13; ++line) cut = journal.find('\n', cut) + 1;
  { std::ofstream(out / "evaluations.csv", std::ios::trunc) << journal.substr(0, cut); }
  fs::remove(out / "summary.json");
  std::vector<std::string> resumed = args(out, "1", "sub-violations");
  resumed.push_back("--resume");
  ASSERT_EQ(scenfuzz(resumed).exit_code, 0);
  EXPECT_EQ(journal_of(out), journal_of(reference));
  EXPECT_EQ(law_coverage_of(out), law_coverage_of(reference));
}

}  // namespace
}  // namespace scenfuzz
