// A reactive lane follower asked to start faster than the bends ahead allow starts as fast as they
// do, and the run says so: a warning naming the actor, at its initial speed, with the speed it
// starts at (shortfall_warnings.hpp, warn_reactive_start).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lang/number_format.hpp"
#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

// The built-in "curve": fwd_0's 90-degree left bend (radius 100 m) begins at s = 100.
std::string tractor_before_the_bend(double speed) {
  return R"(
ego_init_state = ("fwd_0"->10, , 10);
ego_vehicle = AV(ego_init_state, ("fwd_0"->350), ("Lincoln2017MKZ", white));
tractor_init_state = ("fwd_0"->95, , )" +
         std::to_string(speed) + R"();
tractor = Vehicle(tractor_init_state, uniform(tractor_init_state), ("fwd_0"->362), ("Truck", green));
scenario = CreateScenario{load("curve"); ego_vehicle; {tractor}; {}; {}; Environment(10:40, {sunny: 0.6});};
)";
}

TEST(ReactiveStartWarningTest, ATooFastStartIsWarnedAboutWithTheSpeedItStartsAt) {
  test::SimulatedRun run = test::simulate_text(tractor_before_the_bend(30));
  ASSERT_TRUE(run.trace) << run.errors;
  const TraceActor& tractor = run.trace->actors[*run.trace->find_actor("tractor")];
  const double start = tractor.speed.front();
  ASSERT_LT(start, 29);
  EXPECT_NE(run.errors.find("tractor cannot start at 30 m/s"), std::string::npos) << run.errors;
  const std::string starts_at = format_number(std::round(start * 10) / 10) + " m/s";
  EXPECT_NE(run.errors.find("allow " + starts_at), std::string::npos)
      << run.errors << "(starts at " << start << ")";
  EXPECT_NE(run.errors.find("warning"), std::string::npos) << run.errors;
}

TEST(ReactiveStartWarningTest, AStartTheBendsAllowIsNotWarnedAbout) {
  test::SimulatedRun run = test::simulate_text(tractor_before_the_bend(8));
  ASSERT_TRUE(run.trace) << run.errors;
  EXPECT_EQ(run.errors.find("cannot start"), std::string::npos) << run.errors;
}

}  // namespace
}  // namespace scenfuzz
