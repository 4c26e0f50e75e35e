// `scenfuzz bench` run as a user runs it, on small budgets: the falsification table and its
// --first-only shortcut (the same first findings as whole runs), the chasing-cars protocol, the
// parallel check, and errors for bad arguments.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "command_runner.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using test::Outcome;
using test::source_file;

const std::string kPullOut = source_file("corpora/benchmarks/falsification/side_road_pull_out.avu");

// The rows of the first table of `bench falsification` as lists of cells (split at runs of two
// or more spaces; a continuation row's empty scenario and dims cells are dropped).
std::vector<std::vector<std::string>> falsification_rows(const std::string& out) {
  std::istringstream in(out);
  std::string line;
  std::vector<std::vector<std::string>> rows;
  bool in_table = false;
  while (std::getline(in, line)) {
    if (line.starts_with("scenario ")) {
      in_table = true;
      continue;
    }
    if (!in_table) continue;
    if (line.empty()) break;
    std::vector<std::string> cells;
    const std::regex gap("\\s{2,}");
    for (std::sregex_token_iterator cell(line.begin(), line.end(), gap, -1), end; cell != end;
         ++cell) {
      if (!cell->str().empty()) cells.push_back(*cell);
    }
    rows.push_back(cells);
  }
  return rows;
}

class BenchCommandTest : public test::CommandTest {};

TEST_F(BenchCommandTest, FirstOnlyGivesTheSameFirstFindingsAsWholeRuns) {
  const std::vector<std::string> args = {
      "bench",    "falsification", "--algos", "ga,random", "--seeds", "3",
      "--budget", "150",           "-j",      "2",         kPullOut};
  const Outcome whole = scenfuzz(args);
  std::vector<std::string> first_args = args;
  first_args.push_back("--first-only");
  const Outcome first = scenfuzz(first_args);
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.out.find("each run stopping at its first finding"), std::string::npos);
  const auto whole_rows = falsification_rows(whole.out);
  const auto first_rows = falsification_rows(first.out);
  ASSERT_EQ(whole_rows.size(), 2u) << whole.out;
  ASSERT_EQ(first_rows.size(), 2u) << first.out;
  for (std::size_t row = 0; row < 2; ++row) {
    const auto& full = whole_rows[row];
    const auto& quick = first_rows[row];
    ASSERT_EQ(full.size(), quick.size());
    // algorithm, first finding and runs with one agree; findings per 500 are not measured.
    const std::size_t algorithm = full.size() - 5;
    for (std::size_t cell = algorithm; cell < algorithm + 3; ++cell) {
      EXPECT_EQ(full[cell], quick[cell]) << whole.out << first.out;
    }
    EXPECT_NE(full[algorithm + 3], "-");
    EXPECT_EQ(quick[algorithm + 3], "-");
  }
  EXPECT_NE(whole.out.find("random/ga"), std::string::npos);
}

TEST_F(BenchCommandTest, ChasingCarsReportsEachRequirementBesideThePublishedFigures) {
  const Outcome outcome = scenfuzz({"bench", "cc", "--runs", "2", "--requirements", "CC1,CC3",
                                    "--segments", "5", "--budget", "200", "-j", "2"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  // CC1 falls to a few simulations of full throttle and brake: both runs falsify it.
  EXPECT_TRUE(std::regex_search(outcome.out, std::regex("\\nCC1 +2/2 ")));
  EXPECT_TRUE(std::regex_search(outcome.out, std::regex("\\nCC3 +[0-2]/2 ")));
  EXPECT_EQ(outcome.out.find("\nCC2 "), std::string::npos);
  EXPECT_NE(outcome.out.find("zlscheck 2020"), std::string::npos);
}

TEST_F(BenchCommandTest, ParallelFindsTheSameWithOneAndTwoThreads) {
  const Outcome outcome = scenfuzz({"bench", "parallel", "--budget", "40", kPullOut});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("speed-up of -j 2 over -j 1"), std::string::npos);
  EXPECT_NE(outcome.out.find("same findings: yes"), std::string::npos) << outcome.out;
}

TEST_F(BenchCommandTest, BadArgumentsAreUsageErrors) {
  const Outcome no_seeds = scenfuzz({"bench", "falsification", "--seeds", "0", kPullOut});
  EXPECT_EQ(no_seeds.exit_code, 2);
  EXPECT_NE(no_seeds.err.find("--seeds: expected a whole number from 1"), std::string::npos)
      << no_seeds.err;
  // Negative counts are refused, not wrapped to 2^64 - 1.
  for (const char* option : {"--runs", "--segments", "--budget"}) {
    const Outcome negative = scenfuzz({"bench", "cc", option, "-1"});
    EXPECT_EQ(negative.exit_code, 2) << option;
    EXPECT_NE(negative.err.find(option), std::string::npos) << negative.err;
  }
  const Outcome unknown =
      scenfuzz({"bench", "falsification", "--algos", "ga,nlopt:LN_NOPE", "--seeds", "1", kPullOut});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("LN_NOPE"), std::string::npos) << unknown.err;
  const Outcome missing = scenfuzz({"bench", "falsification", "no/such/file.avu"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no/such/file.avu"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace scenfuzz
