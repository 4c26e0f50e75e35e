// `scenfuzz reconstruct` end to end (docs/accident.md, "Reconstruction", "Testing a driver"):
// every corpus accident reconstructs within the default budget of 500 simulations, as described,
// and the written scenario is a valid AVUnit file that `scenfuzz run` replays; the driver under
// test is put in the ego's place, and a collision it could have avoided is a finding; the same
// seed gives the same reconstruction and verdict for any thread count; bad input is an error
// naming the file or the option.
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
  ASSERT_NE(run.exit_code, 2) << run.out << run.err;
  EXPECT_NE(run.out.find("reconstructed " + path + " in "), std::string::npos) << run.out;
  const nlohmann::json result = summary(out);
  // The reference driver was tested in the victim's place: exit 1 exactly for a finding.
  const nlohmann::json& driver = result["driver_test"];
  ASSERT_TRUE(driver.is_object()) << result.dump(2);
  EXPECT_EQ(driver["driver"], "the reference driver");
  EXPECT_EQ(run.exit_code == 1, driver["finding"].get<bool>()) << driver.dump(2);
  EXPECT_NE(run.out.find("driver test: "), std::string::npos) << run.out;
  EXPECT_TRUE(fs::exists(out / "driver_trace.svg"));
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
  EXPECT_EQ(summary(one)["driver_test"]["verdict"], summary(two)["driver_test"]["verdict"]);
  EXPECT_EQ(slurp(one / "driver_trace.csv"), slurp(two / "driver_trace.csv"));
}

TEST_F(ReconstructCommandTest, ReplayedVehiclesDriveOnPastTheCrashAndDoNotBlockTheEgo) {
  // The truck of the reconstruction hit car1 in the junction; in the driver test it drives on
  // through it, so the reference driver in car1's place gets past the scene.
  const fs::path out = dir_ / "out";
  const Outcome run = scenfuzz(
      {"reconstruct", "--out", out.string(), source_file("corpora/accident/left_turn_across.acc")});
  ASSERT_NE(run.exit_code, 2) << run.err;
  const nlohmann::json driver = summary(out)["driver_test"];
  EXPECT_TRUE(driver["reached_target"].get<bool>() || !driver["collision"].is_null())
      << driver.dump(2);
}

TEST_F(ReconstructCommandTest, TheEgoIsTheNamedVehicleInTheWrittenScenario) {
  const fs::path out = dir_ / "out";
  const Outcome run = scenfuzz({"reconstruct", "--ego", "truck1", "--out", out.string(),
                                source_file("corpora/accident/carsim_crossroad_tree.acc")});
  ASSERT_NE(run.exit_code, 2) << run.err;
  EXPECT_NE(slurp(out / "reconstruction.avu").find("truck1 = AV("), std::string::npos);
  // The driver under test was put in the truck's place too.
  EXPECT_EQ(summary(out)["driver_test"]["ego"], "truck1");
  EXPECT_NE(run.out.find("driver test: the reference driver in truck1's place"), std::string::npos)
      << run.out;
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
  // Nothing could be judged of a driver: exit 2, with the closest run still written.
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.out.find("not reconstructed"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("no driver was tested"), std::string::npos) << run.err;
  EXPECT_FALSE(summary(out)["reconstructed"].get<bool>());
  EXPECT_GT(summary(out)["robustness"].get<double>(), 0);
  EXPECT_TRUE(summary(out)["driver_test"].is_null());
}

#ifdef SCENFUZZ_TEST_PLUGIN_DIR
std::string plugin(const std::string& name) {
  return std::string(SCENFUZZ_TEST_PLUGIN_DIR) + "/lib" + name + ".so";
}

TEST_F(ReconstructCommandTest, ADriverThatDoesNotBrakeForAnAvoidableCrashIsAFinding) {
  // In the side impact, car1 runs the light and hits car2; a driver that holds its speed whatever
  // it sees, in car2's place, is hit though it had three seconds to brake.
  const fs::path out = dir_ / "out";
  const std::string path = source_file("corpora/accident/side_impact_stop_sign.acc");
  const Outcome run =
      scenfuzz({"reconstruct", "--ego-plugin", plugin("steady"), "--out", out.string(), path});
  ASSERT_EQ(run.exit_code, 1) << run.out << run.err;
  const std::string verdict =
      "driver test: finding: " + plugin("steady") + " in car2's place: hit by car1";
  EXPECT_NE(run.out.find(verdict), std::string::npos) << run.out;
  const nlohmann::json driver = summary(out)["driver_test"];
  EXPECT_EQ(driver["verdict"], "avoidable");
  EXPECT_TRUE(driver["finding"].get<bool>());
  EXPECT_EQ(driver["responsibility"]["blame"], "other");
  const nlohmann::json& avoid = driver["avoidability"];
  EXPECT_TRUE(avoid["avoidable"].get<bool>());
  EXPECT_NEAR(avoid["brake_time"].get<double>(), avoid["conflict_time"].get<double>() + 1, 1e-9);
  EXPECT_GT(avoid["clearance"].get<double>(), 0);
  EXPECT_LT(avoid["brake_time"].get<double>(), driver["collision"]["time"].get<double>());

  // Given four seconds to answer, no driver could have braked in time.
  const Outcome slow = scenfuzz({"reconstruct", "--ego-plugin", plugin("steady"), "--rss",
                                 "response_time_ego=4", "--out", out.string(), path});
  EXPECT_EQ(slow.exit_code, 0) << slow.out << slow.err;
  EXPECT_EQ(summary(out)["driver_test"]["verdict"], "unavoidable");
}

TEST_F(ReconstructCommandTest, ADriverThatCrashesIsAFindingAndOneThatCannotLoadAnError) {
  const fs::path out = dir_ / "out";
  const std::string path = source_file("corpora/accident/rear_end_red_light.acc");
  const Outcome crash =
      scenfuzz({"reconstruct", "--ego-plugin", plugin("crashing"), "--out", out.string(), path});
  EXPECT_EQ(crash.exit_code, 1) << crash.out << crash.err;
  EXPECT_EQ(summary(out)["driver_test"]["verdict"], "ego_failure");
  EXPECT_EQ(summary(out)["driver_test"]["ego_failure"]["kind"], "ego_crash");
  const Outcome missing = scenfuzz(
      {"reconstruct", "--ego-plugin", plugin("missing_symbol"), "--out", out.string(), path});
  EXPECT_EQ(missing.exit_code, 2) << missing.out << missing.err;
  EXPECT_NE(missing.err.find("the driver could not be tested"), std::string::npos) << missing.err;
}
#endif  // SCENFUZZ_TEST_PLUGIN_DIR

}  // namespace
