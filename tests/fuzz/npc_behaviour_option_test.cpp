// `--npc-behaviour` on the command line overrides the scenario's own switch everywhere, the
// setup's warnings included: a scripted NPC keeps its given speed whatever the bends ahead, so
// the reactive start-speed warning ("cannot start at ...") must not be printed for it.
#include <gtest/gtest.h>

#include <string>

#include "command_runner.hpp"

namespace scenfuzz {
namespace {

// The built-in "curve": fwd_0's 90-degree bend (radius 100 m) begins at s = 100, too sharp for a
// tractor starting at 30 m/s just before it.
constexpr const char* kTractorBeforeTheBend = R"(
ego_init_state = ("fwd_0"->10, , 10);
ego_vehicle = AV(ego_init_state, ("fwd_0"->350), ("Lincoln2017MKZ", white));
tractor_init_state = ("fwd_0"->95, , 30);
tractor = Vehicle(tractor_init_state, uniform(tractor_init_state), ("fwd_0"->362), ("Truck", green));
scenario = CreateScenario{load("curve"); ego_vehicle; {tractor}; {}; {}; Environment(10:40, {sunny: 0.6});};
)";

class NpcBehaviourOptionTest : public test::CommandTest {};

TEST_F(NpcBehaviourOptionTest, ReactiveByDefaultWarnsOfTheStartTheBendsForbid) {
  const std::string file = write("tractor.avu", kTractorBeforeTheBend);
  test::Outcome run = scenfuzz({"run", file, "--out", (dir_ / "out").string()});
  EXPECT_NE(run.err.find("tractor cannot start at 30 m/s"), std::string::npos) << run.err;
}

TEST_F(NpcBehaviourOptionTest, ScriptedOnTheCommandLineIsNotWarnedAboutAReactiveStart) {
  const std::string file = write("tractor.avu", kTractorBeforeTheBend);
  test::Outcome run =
      scenfuzz({"run", file, "--npc-behaviour", "scripted", "--out", (dir_ / "out").string()});
  EXPECT_NE(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err.find("cannot start"), std::string::npos) << run.err;
}

TEST_F(NpcBehaviourOptionTest, ScriptedOnTheCommandLineReachesTheSearchSetupToo) {
  // The search refuses a concrete file ("nothing to search"): a logical copy, its tractor's
  // speed a range.
  std::string text = kTractorBeforeTheBend;
  text.replace(text.find(", 30);"), 6, ", range(29, 30));");
  const std::string logical = write("logical.avu", text);
  test::Outcome scripted = scenfuzz({"--budget", "2", "--npc-behaviour", "scripted", logical,
                                     "--out", (dir_ / "scripted").string()});
  EXPECT_NE(scripted.exit_code, 2) << scripted.err;
  EXPECT_EQ(scripted.err.find("cannot start"), std::string::npos) << scripted.err;
  test::Outcome reactive =
      scenfuzz({"--budget", "2", logical, "--out", (dir_ / "reactive").string()});
  EXPECT_NE(reactive.err.find("cannot start"), std::string::npos) << reactive.err;
}

}  // namespace
}  // namespace scenfuzz
