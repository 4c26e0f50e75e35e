// LawBreaker's traffic_rule_tests files (the 13 laws asserted together) run unchanged on the
// Apollo san_francisco map and `scenfuzz run` judges their spec; so do our own law files in the
// same style (tests/oracle/data/laws: a straight drive through a junction, a lane change, a
// night drive in fog), and `check` finds no name in them the oracle cannot compute.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/fuzz/command_runner.hpp"
#include "tests/support/shared_dir.hpp"

namespace scenfuzz {
namespace {

using scenfuzz::test::Outcome;
using LawFilesRunTest = scenfuzz::test::CommandTest;

std::vector<std::string> law_files() {
  const std::filesystem::path shared = scenfuzz::test::shared_dir() / "examples" / "scenest";
  const std::filesystem::path ours =
      std::filesystem::path(SCENFUZZ_SOURCE_DIR) / "tests" / "oracle" / "data" / "laws";
  return {(shared / "lawbreaker__traffic_rule_tests__intersection_turn_left.scenest").string(),
          (shared / "lawbreaker__input-test.scenest").string(),
          (ours / "intersection_straight.scenest").string(),
          (ours / "lane_change_left.scenest").string(), (ours / "night_fog.scenest").string()};
}

TEST_F(LawFilesRunTest, TheThirteenLawSpecIsJudgedOnSanFrancisco) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const std::string maps = (scenfuzz::test::shared_dir() / "maps" / "apollo").string();
  for (const std::string& path : law_files()) {
    const Outcome check = scenfuzz({"check", path});
    SCOPED_TRACE(path + "\n" + check.err);
    EXPECT_EQ(check.exit_code, 0);
    EXPECT_EQ(check.err.find("does not compute"), std::string::npos);
    EXPECT_EQ(check.err.find("unknown"), std::string::npos);

    const Outcome run = scenfuzz({"run", "--map-path", maps, "--json", path});
    SCOPED_TRACE(run.err);
    EXPECT_TRUE(run.exit_code == 0 || run.exit_code == 1) << "the spec was judged";
    const nlohmann::json report = nlohmann::json::parse(run.out);
    EXPECT_EQ(report.at("map"), "san_francisco");
    const nlohmann::json& specs = report.at("specs");
    ASSERT_EQ(specs.size(), 1u);
    EXPECT_NE(specs[0]["verdict"], "not judged") << specs[0].dump();
    EXPECT_TRUE(specs[0]["robustness"].is_number()) << specs[0].dump();
    EXPECT_EQ(run.exit_code == 1, specs[0]["violated"] == true);
  }
}

}  // namespace
}  // namespace scenfuzz
