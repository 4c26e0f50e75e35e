// Specs the oracle cannot judge (they read a signal it does not compute on simulated traces):
// `check` lists every place at once, `run` judges the other specs and reports these as not
// judged, the search targets the judgeable specs and says which were not judged.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/fuzz/command_runner.hpp"

namespace scenfuzz {
namespace {

using scenfuzz::test::Outcome;
using NotJudgedSpecsTest = scenfuzz::test::CommandTest;

// `blink` and `arrow` read blinking and arrow lights, which no map or run has; `fast` is judged
// (the ego drives at 36 km/h).
std::string scenario(const std::string& start_speed) {
  return "ego = AV((\"east_0\"->50, , " + start_speed +
         "), (\"east_0\"->200));\n"
         "scenario = CreateScenario{load(\"straight\"); ego; {}; {}; {};};\n"
         "Trace trace = EXE(scenario);\n"
         "blink = G (~trafficLightAhead.isBlinking);\n"
         "arrow = G (trafficLightAhead.direction.color == green | "
         "trafficLightAhead.direction.isBlinking);\n"
         "fast = G (speed < 20);\n"
         "trace |= blink;\n"
         "trace |= arrow;\n"
         "trace |= fast;\n";
}

TEST_F(NotJudgedSpecsTest, CheckListsEveryPlaceOfAnUncomputedSignalAtOnce) {
  const std::string path = write("lights.avu", scenario("10"));
  const Outcome check = scenfuzz({"check", path});
  EXPECT_EQ(check.exit_code, 0) << "the file is good; only the oracle lacks the signals";
  for (const std::string& place :
       {path + ":4:13: warning: the oracle does not compute 'trafficLightAhead.isBlinking'",
        path + ":5:12: warning: the oracle does not compute 'trafficLightAhead.direction.color'",
        path +
            ":5:57: warning: the oracle does not compute 'trafficLightAhead.direction.isBlinking'"})
    EXPECT_NE(check.err.find(place), std::string::npos) << place << "\n" << check.err;
  EXPECT_NE(check.err.find("spec 'arrow' will not be judged"), std::string::npos) << check.err;
}

TEST_F(NotJudgedSpecsTest, RunJudgesTheOtherSpecsAndReportsTheseAsNotJudged) {
  const std::string path = write("lights.avu", scenario("10"));
  const Outcome run = scenfuzz({"run", "--duration", "3", "--out", (dir_ / "run").string(), path});
  EXPECT_EQ(run.exit_code, 1) << "fast is violated\n" << run.err;
  EXPECT_NE(run.out.find("spec blink: not judged: " + path +
                         ":4:13: the oracle does not compute 'trafficLightAhead.isBlinking' on "
                         "simulated traces yet"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("spec arrow: not judged: " + path + ":5:12:"), std::string::npos);
  // 36 km/h at the start and faster after: at least 16 km/h over 20.
  EXPECT_NE(run.out.find("spec fast: robustness -"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("violated by 'speed < 20'"), std::string::npos) << run.out;

  const Outcome json = scenfuzz({"run", "--json", "--duration", "3", path});
  EXPECT_EQ(json.exit_code, 1) << json.err;
  const nlohmann::json specs = nlohmann::json::parse(json.out).at("specs");
  ASSERT_EQ(specs.size(), 3u);
  EXPECT_EQ(specs[0]["verdict"], "not judged");
  EXPECT_TRUE(specs[0]["robustness"].is_null());
  EXPECT_EQ(specs[0]["violated"], false);
  EXPECT_EQ(specs[0]["not_judged_location"], path + ":4:13");
  EXPECT_EQ(specs[2]["verdict"], "violated");
}

TEST_F(NotJudgedSpecsTest, RunWithNoJudgeableSpecSaysSoAndExitsTwo) {
  std::string text = scenario("10");
  text.erase(text.find("trace |= fast;\n"));
  const std::string path = write("lights.avu", text);
  const Outcome run = scenfuzz({"run", "--duration", "2", path});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("could be judged on the simulated trace"), std::string::npos) << run.err;
  EXPECT_NE(run.out.find("spec blink: not judged"), std::string::npos) << run.out;
}

TEST_F(NotJudgedSpecsTest, TheSearchTargetsTheJudgeableSpecsAndNamesTheOthers) {
  const std::string path = write("lights.avu", scenario("range(8.0, 12.0)"));
  const std::string out = (dir_ / "out").string();
  const Outcome search =
      scenfuzz({"--budget", "4", "-j", "2", "--duration", "2", "--out", out, path});
  EXPECT_EQ(search.exit_code, 1) << search.err;
  EXPECT_NE(search.err.find("scenfuzz: note: spec blink is not judged: " + path + ":4:13:"),
            std::string::npos)
      << search.err;
  EXPECT_NE(search.out.find("best fast:"), std::string::npos) << search.out;
  EXPECT_EQ(search.out.find("best blink"), std::string::npos) << search.out;
  EXPECT_NE(
      search.out.find("not judged: spec arrow: " + path +
                      ":5:12: the oracle does not compute 'trafficLightAhead.direction.color'"),
      std::string::npos)
      << search.out;
}

// No fog, so `G (fog >= 0)` has robustness exactly 0 at every sample: satisfied in RTAMT's
// convention (the default), violated in LawBreaker's (--violation-at-zero). (`G (speed >= 0)` of
// an ego starting from standing is 0 only at t = 0: the start state's, not a violation.)
TEST_F(NotJudgedSpecsTest, ViolationAtZeroFlipsARobustnessZeroVerdict) {
  const std::string path =
      write("standing.avu",
            "ego = AV((\"east_0\"->50, , 0), (\"east_0\"->200));\n"
            "scenario = CreateScenario{load(\"straight\"); ego; {}; {}; {};};\n"
            "Trace trace = EXE(scenario);\n"
            "moving = G (fog >= 0);\n"
            "trace |= moving;\n");
  const Outcome rtamt = scenfuzz({"run", "--json", "--duration", "2", path});
  EXPECT_EQ(rtamt.exit_code, 0) << rtamt.err;
  const nlohmann::json satisfied = nlohmann::json::parse(rtamt.out).at("specs").at(0);
  EXPECT_EQ(satisfied["robustness"], 0.0);
  EXPECT_EQ(satisfied["verdict"], "satisfied");

  const Outcome lawbreaker =
      scenfuzz({"run", "--json", "--violation-at-zero", "--duration", "2", path});
  EXPECT_EQ(lawbreaker.exit_code, 1) << lawbreaker.err;
  const nlohmann::json violated = nlohmann::json::parse(lawbreaker.out).at("specs").at(0);
  EXPECT_EQ(violated["robustness"], 0.0);
  EXPECT_EQ(violated["verdict"], "violated");

  // The search counts it as a finding too.
  const std::string out = (dir_ / "out").string();
  const Outcome search =
      scenfuzz({"--budget", "2", "-j", "2", "--duration", "2", "--violation-at-zero", "--mutate",
                "speed=0", "--out", out, path});
  EXPECT_EQ(search.exit_code, 1) << search.err << search.out;
}

}  // namespace
}  // namespace scenfuzz
