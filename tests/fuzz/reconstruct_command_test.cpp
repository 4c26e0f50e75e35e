// `scenfuzz reconstruct` end to end (docs/accident.md, "Reconstruction"): every corpus accident
// reconstructs within the default budget of 500 simulations, as described, and the written
// scenario is a valid AVUnit file that `scenfuzz run` replays; the same seed gives the same
// reconstruction for any thread count; bad input is an error naming the file or the option.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_runner.hpp"

namespace {

namespace fs = std::filesystem;
using scenfuzz::test::Outcome;
using scenfuzz::test::slurp;
using scenfuzz::test::source_file;

class ReconstructCommandTest : public scenfuzz::test::CommandTest {
 protected:
  nlohmann::json summary(const fs::path& out) {
    return nlohmann::json::parse(slurp(out / "summary.json"));
  }
};

class CorpusAccident : public ReconstructCommandTest,
                       public ::testing::WithParamInterface<const char*> {};

TEST_P(CorpusAccident, ReconstructsWithinTheDefaultBudgetAsDescribed) {
  const fs::path out = dir_ / "out";
  const std::string path = source_file(std::string("corpora/accident/") + GetParam() + ".acc");
  const Outcome run = scenfuzz({"reconstruct", "--out", out.string(), "-j", "2", path});
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("reconstructed " + path + " in "), std::string::npos) << run.out;
  const nlohmann::json result = summary(out);
  EXPECT_TRUE(result["reconstructed"].get<bool>());
  EXPECT_LE(result["simulations"].get<int>(), 500);
  EXPECT_LT(result["robustness"].get<double>(), 0);
  for (const nlohmann::json& collision : result["collisions"]) {
    EXPECT_TRUE(collision["happened"].get<bool>()) << collision.dump();
    EXPECT_TRUE(collision["as_described"].get<bool>()) << collision.dump();
  }
  // The simulations each took, for docs/accident.md's table.
  std::cout << "[ simulations ] " << GetParam() << ": " << result["simulations"] << "\n";
  // The written scenario reads as AVUnit, and `run` replays it with the driver under test.
  const std::string scenario = (out / "reconstruction.avu").string();
  const Outcome check = scenfuzz({"check", scenario});
  EXPECT_EQ(check.exit_code, 0) << check.err << slurp(scenario);
  const Outcome replay = scenfuzz({"run", "--out", (dir_ / "replay").string(), scenario});
  EXPECT_NE(replay.exit_code, 2) << replay.err;
  EXPECT_TRUE(fs::exists(out / "trace.svg"));
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusAccident,
                         ::testing::Values("carsim_crossroad_tree", "rear_end_red_light",
                                           "head_on_overtake", "side_impact_stop_sign",
                                           "left_turn_across", "lane_change_sideswipe"));

TEST_F(ReconstructCommandTest, TheSameSeedGivesTheSameReconstructionForAnyThreadCount) {
  const std::string path = source_file("corpora/accident/left_turn_across.acc");
  const fs::path one = dir_ / "one", two = dir_ / "two";
  ASSERT_EQ(
      scenfuzz({"reconstruct", "--seed", "7", "-j", "1", "--out", one.string(), path}).exit_code,
      0);
  ASSERT_EQ(
      scenfuzz({"reconstruct", "--seed", "7", "-j", "2", "--out", two.string(), path}).exit_code,
      0);
  EXPECT_EQ(summary(one)["parameters"], summary(two)["parameters"]);
  EXPECT_EQ(summary(one)["simulations"], summary(two)["simulations"]);
  EXPECT_EQ(slurp(one / "reconstruction.avu"), slurp(two / "reconstruction.avu"));
}

TEST_F(ReconstructCommandTest, TheEgoIsTheNamedVehicleInTheWrittenScenario) {
  const fs::path out = dir_ / "out";
  const Outcome run = scenfuzz({"reconstruct", "--ego", "truck1", "--out", out.string(),
                                source_file("corpora/accident/carsim_crossroad_tree.acc")});
  ASSERT_NE(run.exit_code, 2) << run.err;
  EXPECT_NE(slurp(out / "reconstruction.avu").find("truck1 = AV("), std::string::npos);
}

TEST_F(ReconstructCommandTest, BadInputIsAnErrorNamingTheFileOrTheOption) {
  Outcome run = scenfuzz({"reconstruct", source_file("corpora/avunit/cut_in_straight.avu")});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("reconstruct reads an accident description (.acc)"), std::string::npos)
      << run.err;
  const std::string bad = write("bad.acc", "STATIC [ ROAD [ KIND = crosroad; ] ]");
  run = scenfuzz({"reconstruct", bad});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("bad.acc:1:24: error:"), std::string::npos) << run.err;
  run = scenfuzz(
      {"reconstruct", "--ego", "bus9", source_file("corpora/accident/carsim_crossroad_tree.acc")});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--ego names 'bus9', which is no VEHICLE"), std::string::npos) << run.err;
  run = scenfuzz(
      {"reconstruct", "--budget", "0", source_file("corpora/accident/carsim_crossroad_tree.acc")});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--budget"), std::string::npos) << run.err;
  run = scenfuzz({"reconstruct", write("missing_dir.acc", "")});
  EXPECT_EQ(run.exit_code, 2);
}

TEST_F(ReconstructCommandTest, AnAccidentThatCannotHappenIsReportedWithItsClosestRun) {
  // Two cars heading east in one lane each way, the one ahead hitting the one behind with its
  // front: a vehicle that only drives forward cannot.
  const std::string text =
      "STATIC [ ROAD [ KIND = straightroad; ] ]\n"
      "DYNAMIC [\n"
      "  VEHICLE [ ID = car1; KIND = car; INITDIRECTION = east; ]\n"
      "  VEHICLE [ ID = car2; KIND = car; INITDIRECTION = west; ]\n"
      "]\n"
      "ACCIDENT [ COLLISION [ ACTOR = car1, rear; VICTIM = car2, rear; ] ]\n";
  const fs::path out = dir_ / "out";
  const Outcome run =
      scenfuzz({"reconstruct", "--budget", "40", "--out", out.string(), write("no.acc", text)});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.out.find("not reconstructed"), std::string::npos) << run.out;
  EXPECT_FALSE(summary(out)["reconstructed"].get<bool>());
  EXPECT_GT(summary(out)["robustness"].get<double>(), 0);
}

}  // namespace
