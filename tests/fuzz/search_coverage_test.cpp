// The behaviour coverage a search reports in summary.json (docs/coverage.md, "The search's
// coverage"): what a cut-in on the straight road must cover and must not, the union of the
// journal's per-evaluation features, the same for -j 1 and -j 2, and the same after a search
// killed half-way is resumed from its journal.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "command_runner.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using test::slurp;

const std::string kCutIn = test::source_file("corpora/avunit/cut_in_straight.avu");

nlohmann::json coverage_of(const fs::path& out) {
  return nlohmann::json::parse(slurp(out / "summary.json")).at("coverage");
}

std::vector<std::string> names_of(const nlohmann::json& coverage) {
  return coverage.at("names").get<std::vector<std::string>>();
}

bool has_prefix(const std::vector<std::string>& names, const std::string& prefix) {
  for (const std::string& name : names)
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

// The union of evaluations.csv's coverage column.
std::set<std::string> journal_union(const fs::path& out) {
  const auto rows = test::read_csv(slurp(out / "evaluations.csv"));
  const auto& header = rows.front();
  const auto column = static_cast<std::size_t>(std::find(header.begin(), header.end(), "coverage") -
                                               header.begin());
  EXPECT_LT(column, header.size());
  std::set<std::string> features;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const std::string& text = rows[r].at(column);
    for (std::size_t start = 0; start < text.size();) {
      const std::size_t end = std::min(text.find(';', start), text.size());
      features.insert(text.substr(start, end - start));
      start = end + 1;
    }
  }
  return features;
}

class SearchCoverageTest : public test::CommandTest {
 protected:
  std::vector<std::string> args(const fs::path& out, const std::string& jobs) {
    return {"--budget", "60", "--seed", "4", "-j", jobs, "--quiet", "--out", out.string(), kCutIn};
  }
};

TEST_F(SearchCoverageTest, ACutInOnTheStraightRoadCoversItsCarAndNothingOfJunctions) {
  const fs::path out = dir_ / "one";
  ASSERT_EQ(scenfuzz(args(out, "1")).exit_code, 1);
  const nlohmann::json coverage = coverage_of(out);
  const std::vector<std::string> names = names_of(coverage);
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_EQ(coverage.at("features").get<std::size_t>(), names.size());
  // The cutter: a car ahead in the ego's lane and one ahead beside it before it merged.
  EXPECT_TRUE(has_prefix(names, "interaction.car.F.")) << coverage.dump();
  EXPECT_TRUE(has_prefix(names, "interaction.car.FSL.") ||
              has_prefix(names, "interaction.car.FSR."))
      << coverage.dump();
  // Nothing but a car on a straight road in daylight, without laws.
  EXPECT_FALSE(has_prefix(names, "interaction.pedestrian.")) << coverage.dump();
  EXPECT_FALSE(has_prefix(names, "interaction.bicycle.")) << coverage.dump();
  const std::vector<std::string> environment = {"light.day", "weather.clear"};
  for (const std::string& name : environment)
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  const nlohmann::json& families = coverage.at("by_family");
  EXPECT_EQ(families.at("road"), 0);
  EXPECT_EQ(families.at("law"), 0);
  EXPECT_EQ(families.at("weather"), 1);
  EXPECT_EQ(families.at("light"), 1);
  std::size_t total = 0;
  for (const auto& [family, count] : families.items()) total += count.get<std::size_t>();
  EXPECT_EQ(total, names.size());
  // The summary's names are exactly the union of the journal's per-evaluation features.
  const std::set<std::string> journal = journal_union(out);
  EXPECT_EQ(std::vector<std::string>(journal.begin(), journal.end()), names);
}

TEST_F(SearchCoverageTest, TheCoverageIsTheSameForAnyNumberOfJobs) {
  ASSERT_EQ(scenfuzz(args(dir_ / "one", "1")).exit_code, 1);
  ASSERT_EQ(scenfuzz(args(dir_ / "two", "2")).exit_code, 1);
  EXPECT_FALSE(names_of(coverage_of(dir_ / "one")).empty());
  EXPECT_EQ(coverage_of(dir_ / "one"), coverage_of(dir_ / "two"));
}

// A kill leaves a prefix of the journal: cut one there and resume, and the replayed evaluations
// (not simulated again) bring their features back from the journal.
TEST_F(SearchCoverageTest, AResumedSearchReportsTheCoverageOfAnUninterruptedOne) {
  const fs::path reference = dir_ / "reference";
  ASSERT_EQ(scenfuzz(args(reference, "2")).exit_code, 1);
  const nlohmann::json expected = coverage_of(reference);

  const fs::path out = dir_ / "killed";
  ASSERT_EQ(scenfuzz(args(out, "1")).exit_code, 1);
  const std::string journal = slurp(out / "evaluations.csv");
  std::size_t cut = 0;
  for (int line = 0; line < 1 + 20; ++line) cut = journal.find('\n', cut) + 1;
  { std::ofstream(out / "evaluations.csv", std::ios::trunc) << journal.substr(0, cut); }
  fs::remove(out / "summary.json");
  std::vector<std::string> resumed = args(out, "1");
  resumed.push_back("--resume");
  ASSERT_EQ(scenfuzz(resumed).exit_code, 1);
  EXPECT_EQ(coverage_of(out), expected);
  EXPECT_EQ(journal_union(out), journal_union(reference));
}

}  // namespace
}  // namespace scenfuzz
