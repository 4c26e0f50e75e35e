// Honest specs, end to end: a run cut short while the ego progresses is a time-out (its own
// verdict in `run`, no finding in a search); an ego that stopped making progress is a finding
// marked stuck; a --duration shorter than a spec reads is warned of; a spec violated at most
// points of the search's first design is warned of, and its rate is in summary.json; a spec only
// the scenario's start state violates is start-state (its own verdict in `run`, no finding); one
// violated only once a car ran into the ego, not the ego's fault, is other-fault (the same).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_runner.hpp"

namespace scenfuzz {
namespace {

using test::Outcome;
using test::slurp;

// An ego driving 460 m down an empty road at `speed` (a number or a range).
std::string long_drive(const std::string& speed, const std::string& reach = "F") {
  return R"(
ego_target = "east_0"->480;
ego = AV((("east_0"->20), , )" +
         speed + R"(), (ego_target, , ));
scenario = CreateScenario{load("straight"); ego; {}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
reach = )" +
         reach +
         R"( (dis(ego_state, ego_target) <= 2.0);
trace |= reach;
)";
}

// A standing ego rammed from behind by a scripted car at `speed` (a number or a range): its
// clearance spec is broken by the car alone; its speed spec holds throughout.
std::string rammed(const std::string& speed) {
  return R"(
ego = AV(("east_0"->60, , 0), ("east_0"->480));
rammer = Vehicle(("east_0"->10, , )" +
         speed + R"(), Waypoint(("east_0"->200, , 12)), ("east_0"->400));
scenario = CreateScenario{load("straight"); ego; {rammer}; {}; {}; {}; {NPCBehaviour(scripted)};};
Trace trace = EXE(scenario);
clear = G (dis(trace[ego], trace[truth][rammer]) > 0.5);
calm = G (trace[ego].speed <= 30);
trace |= clear;
trace |= calm;
)";
}

class HonestSpecsTest : public test::CommandTest {
 protected:
  Outcome search(const std::string& scenario, std::vector<std::string> extra) {
    std::vector<std::string> args = {"--out", (dir_ / "out").string(), "--seed", "1"};
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back(write("scenario.avu", scenario));
    return scenfuzz(args);
  }
  nlohmann::json summary() const {
    return nlohmann::json::parse(slurp(dir_ / "out" / "summary.json"));
  }
};

TEST_F(HonestSpecsTest, RunReportsATimeOutAsItsOwnVerdict) {
  const std::string file = write("drive.avu", long_drive("10"));
  const Outcome text = scenfuzz({"run", file, "--duration", "10", "--out", ""});
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("spec reach: time-out: the run ended while the ego still made progress"),
            std::string::npos)
      << text.out;
  const Outcome json = scenfuzz({"run", file, "--duration", "10", "--json", "--out", ""});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json spec = nlohmann::json::parse(json.out)["specs"][0];
  EXPECT_EQ(spec["verdict"], "time-out");
  EXPECT_EQ(spec["violated"], false);
  EXPECT_EQ(spec["ending"], "time-out");
  EXPECT_LT(spec["robustness_at_end"].get<double>(), 0.0);
}

// An ego starting at `speed` m/s on a road whose limit is 80 km/h (22.2 m/s): the reference
// driver slows from 26 m/s to 23.0 within 2 s, to 22.2 after. `limit` is the spec's (m/s).
std::string fast_start(const std::string& speed, const std::string& limit) {
  return R"(
ego_target = "east_0"->300;
ego = AV((("east_0"->20), , )" +
         speed + R"(), (ego_target, , ));
scenario = CreateScenario{load("straight"); ego; {}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
limit = G (ego_state.speed <= )" +
         limit + R"();
trace |= limit;
)";
}

TEST_F(HonestSpecsTest, RunReportsAStartStateAsItsOwnVerdict) {
  const std::string file = write("fast.avu", fast_start("26", "23.5"));
  const Outcome text = scenfuzz({"run", file, "--out", ""});
  EXPECT_EQ(text.exit_code, 0) << text.err << text.out;
  EXPECT_NE(
      text.out.find("spec limit: start-state: violated at 0 s by 'ego_state.speed <= 23.5' ("),
      std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("(robustness -2.5) by the scenario's start state; holds from 2 s on"),
            std::string::npos)
      << text.out;
  const Outcome json = scenfuzz({"run", file, "--json", "--out", ""});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json spec = nlohmann::json::parse(json.out)["specs"][0];
  EXPECT_EQ(spec["verdict"], "start-state");
  EXPECT_EQ(spec["violated"], false);
  EXPECT_EQ(spec["ending"], "start-state");
  EXPECT_GT(spec["robustness"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(spec["robustness_as_observed"].get<double>(), -2.5);
  EXPECT_DOUBLE_EQ(spec["start_grace"].get<double>(), 2.0);
  EXPECT_EQ(spec["time"], 0.0);
  // Still above 22.5 m/s at 2 s: the driver's violation, decided.
  const Outcome slower =
      scenfuzz({"run", write("slower.avu", fast_start("26", "22.5")), "--json", "--out", ""});
  EXPECT_EQ(slower.exit_code, 1) << slower.err;
  const nlohmann::json decided = nlohmann::json::parse(slower.out)["specs"][0];
  EXPECT_EQ(decided["verdict"], "violated");
  EXPECT_FALSE(decided.contains("ending"));
}

TEST_F(HonestSpecsTest, RunReportsTheDriversShareOfAViolationTheStartStateMadeWorse) {
  // Still above 22.5 m/s at 2 s: the driver's violation, reported by what the driver did from
  // 2 s on, not by the 26 m/s the file started it at.
  const std::string file = write("slower.avu", fast_start("26", "22.5"));
  const Outcome json = scenfuzz({"run", file, "--json", "--out", ""});
  ASSERT_EQ(json.exit_code, 1) << json.err;
  const nlohmann::json spec = nlohmann::json::parse(json.out)["specs"][0];
  EXPECT_EQ(spec["verdict"], "violated");
  EXPECT_FALSE(spec.contains("ending"));
  const double share = spec["robustness"].get<double>();
  EXPECT_LT(share, 0.0);
  EXPECT_GT(share, -1.0);  // the reference driver is at 23.0 m/s at 2 s
  EXPECT_NEAR(spec["time"].get<double>(), 2.0, 1e-9);
  ASSERT_TRUE(spec.contains("robustness_as_observed")) << spec.dump(2);
  EXPECT_DOUBLE_EQ(spec["robustness_as_observed"].get<double>(), -3.5);
  EXPECT_EQ(spec["time_as_observed"], 0.0);
  EXPECT_DOUBLE_EQ(spec["start_grace"].get<double>(), 2.0);
  const Outcome text = scenfuzz({"run", file, "--out", ""});
  EXPECT_NE(text.out.find(" at 2 s, violated by 'ego_state.speed <= 22.5' ("), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find(") (from the start state -3.5 at 0 s)"), std::string::npos) << text.out;
}

TEST_F(HonestSpecsTest, AFindingTheStartStateMadeWorseIsHeadedByTheDriversShare) {
  const Outcome run = search(fast_start("range(25.5, 26)", "22.5"), {"--budget", "4"});
  ASSERT_EQ(run.exit_code, 1) << run.err << run.out;
  const nlohmann::json summary = this->summary();
  ASSERT_EQ(summary["findings"].size(), 1u) << summary.dump(2);
  const nlohmann::json& finding = summary["findings"][0];
  EXPECT_GT(finding["robustness"].get<double>(), -1.0);  // the share, not the start's -3 or so
  const std::string header = slurp(finding["file"].get<std::string>());
  EXPECT_NE(header.find("spec limit violated, robustness -0."), std::string::npos) << header;
  EXPECT_NE(header.find(" at 2 s (ego_state.speed <= 22.5) (from the start state -3."),
            std::string::npos)
      << header;
}

TEST_F(HonestSpecsTest, ASearchWhoseRunsAllStartTooFastHasNoFinding) {
  const Outcome run = search(fast_start("range(25, 26)", "23.5"), {"--budget", "16"});
  EXPECT_EQ(run.exit_code, 0) << run.err << run.out;
  const nlohmann::json summary = this->summary();
  EXPECT_TRUE(summary["findings"].empty()) << summary.dump(2);
  EXPECT_EQ(summary["start_state"]["limit"], 16);
  EXPECT_EQ(summary["time_outs"]["limit"], 0);
  EXPECT_NE(run.out.find("limit: 16 start-state"), std::string::npos) << run.out;
}

TEST_F(HonestSpecsTest, ADurationShorterThanASpecReadsIsWarnedNamingTheSpec) {
  const std::string file = write("drive.avu", long_drive("10", "F[0:40]"));
  const Outcome run = scenfuzz({"run", file, "--duration", "20", "--out", ""});
  EXPECT_NE(run.err.find("warning: --duration 20 is shorter than spec 'reach' reads (40 s)"),
            std::string::npos)
      << run.err;
  // The default is long enough: no warning.
  const Outcome quiet = scenfuzz({"run", file, "--out", ""});
  EXPECT_EQ(quiet.err.find("shorter than"), std::string::npos) << quiet.err;
}

TEST_F(HonestSpecsTest, ASearchWhoseRunsAllTimeOutHasNoFinding) {
  const Outcome run = search(long_drive("range(8, 12)"), {"--budget", "16", "--duration", "10"});
  EXPECT_EQ(run.exit_code, 0) << run.err << run.out;
  const nlohmann::json summary = this->summary();
  EXPECT_TRUE(summary["findings"].empty()) << summary.dump(2);
  EXPECT_EQ(summary["time_outs"]["reach"], 16);
  EXPECT_NE(run.out.find("reach: 16 time-outs"), std::string::npos) << run.out;
}

TEST_F(HonestSpecsTest, AnEgoStuckBehindAParkedCarIsAFindingMarkedStuck) {
  const Outcome run = search(R"(
ego_target = "east_0"->400;
ego = AV((("east_0"->20), , range(10, 15)), (ego_target, , ));
npc = Vehicle(("east_0"->range(70, 90), , 0.0));
scenario = CreateScenario{load("straight?two_way=0&lanes=1"); ego; {npc}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
reach = F (dis(ego_state, ego_target) <= 2.0);
trace |= reach;
)",
                             {"--budget", "8"});
  ASSERT_EQ(run.exit_code, 1) << run.err << run.out;
  const nlohmann::json summary = this->summary();
  ASSERT_FALSE(summary["findings"].empty());
  const nlohmann::json& finding = summary["findings"][0];
  EXPECT_EQ(finding["ending"], "stuck");
  EXPECT_GT(summary["stuck"]["reach"].get<int>(), 0);
  EXPECT_NE(slurp(finding["file"].get<std::string>()).find("; stuck: the run ended"),
            std::string::npos);
  EXPECT_NE(run.out.find("reach robustness"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find(" stuck"), std::string::npos) << run.out;
}

TEST_F(HonestSpecsTest, ASpecViolatedAtMostPointsOfTheFirstDesignIsWarnedOf) {
  const Outcome run = search(R"(
ego = AV((("east_0"->range(20, 60)), , range(5, 10)), (("east_0"->200), , ));
scenario = CreateScenario{load("straight"); ego; {}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
too_fast = G (ego_state.speed > 100.0);
fine = G (ego_state.speed < 100.0);
trace |= too_fast;
trace |= fine;
)",
                             {"--budget", "40", "--algo", "random", "--spec", "too_fast"});
  ASSERT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("warning: spec 'too_fast' is violated at 16 of the 16 points of the "
                         "search's first design (100 %)"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("ego_state.speed > 100.0"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("its ranges or thresholds are probably wrong"), std::string::npos);
  EXPECT_EQ(run.err.find("spec 'fine'"), std::string::npos) << run.err;
  const nlohmann::json summary = this->summary();
  EXPECT_DOUBLE_EQ(summary["first_design"]["violation_rate"]["too_fast"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(summary["first_design"]["violation_rate"]["fine"].get<double>(), 0.0);
  EXPECT_EQ(summary["first_design"]["points"], 16);
}

TEST_F(HonestSpecsTest, RunReportsAViolationOnlyAnotherRoadUserBroughtAsOtherFault) {
  const std::string file = write("rammed.avu", rammed("15"));
  const Outcome json = scenfuzz({"run", file, "--json", "--out", ""});
  ASSERT_EQ(json.exit_code, 0) << json.err << json.out;
  const nlohmann::json clear = nlohmann::json::parse(json.out)["specs"][0];
  EXPECT_EQ(clear["verdict"], "other-fault");
  EXPECT_EQ(clear["ending"], "other-fault");
  EXPECT_EQ(clear["violated"], false);
  EXPECT_EQ(clear["other"], "rammer");
  EXPECT_LT(clear["robustness_as_observed"].get<double>(), 0);
  EXPECT_GE(clear["robustness"].get<double>(), 0);
  const Outcome text = scenfuzz({"run", file, "--out", ""});
  EXPECT_NE(text.out.find("spec clear: other-fault: violated at "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("only once rammer, whose collision with the ego was not the ego's fault"),
            std::string::npos)
      << text.out;
  // Counted as observed, it is a violation.
  const Outcome all = scenfuzz({"run", file, "--json", "--all-collisions", "--out", ""});
  EXPECT_EQ(all.exit_code, 1) << all.err;
  EXPECT_EQ(nlohmann::json::parse(all.out)["specs"][0]["verdict"], "violated");
}

TEST_F(HonestSpecsTest, ASearchWhoseViolationsOthersBroughtHasNoFinding) {
  const Outcome run = search(rammed("range(14, 16)"), {"--budget", "8"});
  EXPECT_EQ(run.exit_code, 0) << run.err << run.out;
  const nlohmann::json summary = this->summary();
  EXPECT_TRUE(summary["findings"].empty()) << summary.dump(2);
  EXPECT_GT(summary["other_fault"]["clear"].get<int>(), 0) << summary.dump(2);
  EXPECT_NE(run.out.find("clear: "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find(" other-fault (violated only once another road user"), std::string::npos)
      << run.out;
}

}  // namespace
}  // namespace scenfuzz
