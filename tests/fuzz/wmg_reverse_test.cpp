// WMG SDL's Reverse_* manoeuvres end to end, through the real executable: a level-2 file whose
// actors reverse (along the lane, and changing lane) and a level-1 file that says "reverses"
// parse, translate and run, and the trace shows the actors backing up from a standstill.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "command_runner.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using test::Outcome;
using test::slurp;

// Reverser stands 30 to 60 m ahead of the ego in its lane and backs towards it; Shifter, ahead in
// the next lane, backs into the ego's lane.
constexpr const char* kLevel2 = R"(VERSION: 1.0
AUTHOR: 'scenfuzz'
EXTENSION: None

SCENERY ELEMENTS:
DO: 'Two-lane road' [Road2] as:
Junctions: None
Roads:
R1: START
  Road type [Motorway] as [R1]
  with zone as [N/A]
  AND speed limit of [50]
  in a [Urban] environment
  with Number of lanes [2] as [R1.L1, R1.L2]
  Road traffic direction [Left-handed]
  Lane type [Traffic lane]
  Lane markings [Broken line]
  Horizontal road geometry [Straight]
  Vertical road geometry [Level plane]
  Transverse road geometry [Divided]
  Road banking angle [Level Plane]
  with [No] roadside feature
  Length [300 to 500]
  AND Lane width [3.5]
END

DYNAMIC ELEMENTS:
INITIAL:
  Vehicle [Ego] in [R1.L1] at heading angle [0]
  AND Vehicle [Reverser] in [R1.L1]
      with a [Longitudinal] offset of [30 to 60]
      AND at relative position [F]
      with relative heading angle [0] to [Ego]
  AND Vehicle [Shifter] in [R1.L2]
      with a [Longitudinal] offset of [80 to 100]
      AND at relative position [FSL]
      with relative heading angle [0] to [Ego]
  AND Global timer [Clock] = [0]

WHEN: [Ego] is [Going Ahead] at a speed of [20 to 40]
DO: [Reverser]
  PHASE 1: [Reverse_Towards] [-, 5 to 10, 1 to 3] [Ego: 5 to 15, F]
  PHASE 2: [Stop] [-, 0, 1 to 2] [Ego: 5 to 15, F]
  AND: [Shifter]
  PHASE 1: [Reverse_CutIn] [-, 3 to 8, 2 to 4] [Ego: 5 to 20, F]

END: [Clock] >= [15] OR Collision

ENVIRONMENT ELEMENTS:
DO: [Weather1]
  Cloudiness [0 to 8]
  Rainfall [Light Rain: 0]
  Time of the day [Any]
  Illumination [Day] with [Sun] as light source
)";

constexpr const char* kLevel1 = R"(VERSION: 1.0
AUTHOR: 'scenfuzz'

During the day, there is a light, clear sky.
There is no junction present.
R1 is a straight, minor road with light traffic.
There are 2 vehicles, Ego and Car.
Ego is in R1 and Car is in R1.
When Ego is driving, Car reverses towards Ego at its front.
Ego operates autonomously.
)";

class WmgReverseTest : public test::CommandTest {
 protected:
  // Runs `text` at the middle of its search space; 0: no finding, 1: a finding, never a bad
  // input (2) or an internal error.
  nlohmann::json run_trace(const std::string& name, const std::string& text) {
    const Outcome run =
        scenfuzz({"run", write(name, text), "--at", "mid", "--out", (dir_ / "out").string()});
    EXPECT_TRUE(run.exit_code == 0 || run.exit_code == 1) << run.exit_code << "\n" << run.err;
    if (run.exit_code > 1) return {};
    return nlohmann::json::parse(slurp(dir_ / "out" / "trace.json"));
  }
};

const nlohmann::json* actor_named(const nlohmann::json& trace, const std::string& name) {
  for (const nlohmann::json& actor : trace["actors"])
    if (actor["name"] == name) return &actor;
  return nullptr;
}

// Stands at the start, then backs up: reversing at some sample, where x has fallen since the
// start (every road here runs east).
void expect_reverses_from_rest(const nlohmann::json& trace, const std::string& name) {
  const nlohmann::json* actor = actor_named(trace, name);
  ASSERT_NE(actor, nullptr) << name;
  const nlohmann::json& samples = (*actor)["samples"];
  EXPECT_EQ(samples["speed"][0].get<double>(), 0) << name << " starts at rest";
  bool reversed = false;
  for (std::size_t i = 0; i < samples["reversing"].size(); ++i) {
    if (!samples["reversing"][i].get<bool>()) continue;
    reversed = true;
    EXPECT_LT(samples["x"][i].get<double>(), samples["x"][0].get<double>()) << name;
    // Backing into the next lane swings the nose, but it never turns round.
    const double turned = samples["heading"][i].get<double>() - samples["heading"][0].get<double>();
    EXPECT_GT(std::cos(turned), 0) << name << " faces the way it did";
  }
  EXPECT_TRUE(reversed) << name << " never reversed";
}

TEST_F(WmgReverseTest, ALevelTwoFileWithReversingActorsRuns) {
  const nlohmann::json trace = run_trace("reverse.sdl", kLevel2);
  if (trace.is_null()) return;
  expect_reverses_from_rest(trace, "Reverser");
  expect_reverses_from_rest(trace, "Shifter");
}

TEST_F(WmgReverseTest, ALevelOneFileThatSaysReversesRuns) {
  const nlohmann::json trace = run_trace("reverse_level1.sdl", kLevel1);
  if (trace.is_null()) return;
  expect_reverses_from_rest(trace, "Car");
}

}  // namespace
}  // namespace scenfuzz
