// The ego plugin host: the example plugin drives sensibly through it, and plugins that crash,
// hang, fail or lack a symbol cost one PluginDriver an EgoPluginError, never the test process.
#include "physics/ego/plugin_driver.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#if !defined(SCENFUZZ_EXAMPLE_EGO_PLUGIN) || !defined(SCENFUZZ_TEST_PLUGIN_DIR)
#error "tests/CMakeLists.txt passes the plugins' paths"
#endif

namespace scenfuzz {
namespace {

using ::testing::HasSubstr;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string test_plugin(const std::string& name) {
  return std::string(SCENFUZZ_TEST_PLUGIN_DIR) + "/lib" + name + ".so";
}

PluginOptions options_for(const std::string& library, double step_timeout = 2.0) {
  PluginOptions options;
  options.library = library;
  options.step_timeout = step_timeout;
  return options;
}

scenfuzz_ego_config car_config() {
  scenfuzz_ego_config config{};
  config.dt = 0.1;
  config.seed = 1;
  config.vehicle = {4.93, 1.86, 2.85, 40.0, 3.0, 8.0, 0.6};
  config.target_x = std::nan("");
  config.target_y = std::nan("");
  return config;
}

// The ego at the origin heading east at `speed`, nothing seen, no light, sign or target.
scenfuzz_observation open_road(double speed) {
  scenfuzz_observation observation{};
  observation.ego.speed = speed;
  observation.distance_to_target = kInfinity;
  observation.light = SCENFUZZ_LIGHT_NONE;
  observation.light_distance = kInfinity;
  observation.stop_sign_distance = kInfinity;
  return observation;
}

void set_straight_route(scenfuzz_observation& observation, double speed_limit) {
  observation.route_point_count = SCENFUZZ_ROUTE_POINTS;
  for (uint32_t i = 0; i < SCENFUZZ_ROUTE_POINTS; ++i) {
    observation.route[i] = {2.0 * i, 0.0, 0.0, speed_limit};
  }
}

// A left bend of radius 20 m starting at the origin.
void set_left_curve_route(scenfuzz_observation& observation, double speed_limit) {
  const double radius = 20;
  observation.route_point_count = SCENFUZZ_ROUTE_POINTS;
  for (uint32_t i = 0; i < SCENFUZZ_ROUTE_POINTS; ++i) {
    const double angle = 2.0 * i / radius;
    observation.route[i] = {radius * std::sin(angle), radius * (1 - std::cos(angle)), angle,
                            speed_limit};
  }
}

bool reaped(pid_t process) {
  int status = 0;
  return waitpid(process, &status, WNOHANG) == -1 && errno == ECHILD;
}

TEST(PluginDriverExample, AcceleratesFromRestAlongAStraightRoute) {
  PluginDriver driver(options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN), car_config());
  scenfuzz_observation observation = open_road(0);
  set_straight_route(observation, 10);
  const scenfuzz_control control = driver.step(observation);
  EXPECT_GT(control.acceleration, 0.5);
  EXPECT_NEAR(control.steering_angle, 0, 1e-6);
}

TEST(PluginDriverExample, SteersLeftIntoALeftBend) {
  PluginDriver driver(options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN), car_config());
  scenfuzz_observation observation = open_road(5);
  set_left_curve_route(observation, 10);
  EXPECT_GT(driver.step(observation).steering_angle, 0.05);
}

TEST(PluginDriverExample, IndicatesTowardsATurnOfItsRouteAndNotOnAStraightOne) {
  PluginDriver driver(options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN), car_config());
  scenfuzz_observation observation = open_road(5);
  set_left_curve_route(observation, 10);
  const scenfuzz_control turning = driver.step(observation);
  EXPECT_EQ(turning.version, 2u);
  EXPECT_EQ(turning.signals, SCENFUZZ_SIGNAL_LEFT_INDICATOR);
  set_straight_route(observation, 10);
  EXPECT_EQ(driver.step(observation).signals, 0u);
}

TEST(PluginDriverExample, LightsAndWipersAsTheEnvironmentAsks) {
  PluginDriver driver(options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN), car_config());
  scenfuzz_observation observation = open_road(5);
  set_straight_route(observation, 10);
  observation.environment.darkness = 1;
  EXPECT_EQ(driver.step(observation).signals, SCENFUZZ_SIGNAL_LOW_BEAM);
  observation.environment = {0, 0.5, 0.3, 0};
  EXPECT_EQ(driver.step(observation).signals,
            SCENFUZZ_SIGNAL_LOW_BEAM | SCENFUZZ_SIGNAL_FOG_LIGHTS | SCENFUZZ_SIGNAL_WIPERS);
}

TEST(PluginDriverExample, BrakesForARedLightButNotForAGreenOne) {
  PluginDriver driver(options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN), car_config());
  scenfuzz_observation observation = open_road(8);
  set_straight_route(observation, 10);
  observation.light_distance = 10;
  observation.light = SCENFUZZ_LIGHT_GREEN;
  EXPECT_GT(driver.step(observation).acceleration, 0);
  observation.light = SCENFUZZ_LIGHT_RED;
  EXPECT_LT(driver.step(observation).acceleration, -2);
}

TEST(PluginDriverExample, BrakesForAStoppedCarInItsLaneButNotForOneBeside) {
  PluginDriver driver(options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN), car_config());
  scenfuzz_observation observation = open_road(10);
  set_straight_route(observation, 15);
  observation.object_count = 1;
  observation.objects[0] = {7, SCENFUZZ_OBJECT_VEHICLE, 25.0, 3.5, 0.0, 0.0, 4.7, 1.85};
  EXPECT_GT(driver.step(observation).acceleration, 0);  // in the next lane
  observation.objects[0].y = 0.3;
  EXPECT_LT(driver.step(observation).acceleration, -2);
}

TEST(PluginDriverExample, StopsAtItsTarget) {
  PluginDriver driver(options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN), car_config());
  scenfuzz_observation observation = open_road(10);
  set_straight_route(observation, 15);
  observation.distance_to_target = 12;
  EXPECT_LT(driver.step(observation).acceleration, -2);
}

// A closed loop for the example: a road that runs `straight` metres east and then bends left
// with radius 40 m, and a plain kinematic bicycle (rear-axle reference) standing in for
// scenfuzz's.
struct Road {
  double straight = 30;
  double radius = 40;

  scenfuzz_route_point at(double s, double speed_limit) const {
    if (s <= straight) return {s, 0, 0, speed_limit};
    const double angle = (s - straight) / radius;
    return {straight + radius * std::sin(angle), radius * (1 - std::cos(angle)), angle,
            speed_limit};
  }
  // Arc length of the projection of (x, y) and the distance from the centre line.
  void project(double x, double y, double& s, double& lateral) const {
    if (x <= straight) {
      s = x;
      lateral = std::abs(y);
      return;
    }
    s = straight + radius * std::atan2(x - straight, radius - y);
    lateral = std::abs(radius - std::hypot(x - straight, y - radius));
  }
};

struct ClosedLoop {
  Road road;
  PluginDriver driver{options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN), car_config()};
  scenfuzz_observation observation = open_road(0);
  double s = 0;
  double lateral = 0;

  // One step of 0.1 s; the route ahead starts at the ego's projection.
  void step(double speed_limit) {
    const scenfuzz_vehicle vehicle = car_config().vehicle;
    road.project(observation.ego.x, observation.ego.y, s, lateral);
    observation.route_point_count = SCENFUZZ_ROUTE_POINTS;
    for (uint32_t i = 0; i < SCENFUZZ_ROUTE_POINTS; ++i) {
      observation.route[i] = road.at(s + 2.0 * i, speed_limit);
    }
    const scenfuzz_control control = driver.step(observation);
    scenfuzz_ego_state& ego = observation.ego;
    const double dt = 0.1;
    const double acceleration =
        std::clamp(control.acceleration, -vehicle.max_deceleration, vehicle.max_acceleration);
    const double steering =
        std::clamp(control.steering_angle, -vehicle.max_steering_angle, vehicle.max_steering_angle);
    ego.x += ego.speed * std::cos(ego.heading) * dt;
    ego.y += ego.speed * std::sin(ego.heading) * dt;
    ego.heading += ego.speed * std::tan(steering) / vehicle.wheelbase * dt;
    ego.speed = std::max(0.0, ego.speed + acceleration * dt);
    ego.time += dt;
  }
};

TEST(PluginDriverExample, KeepsToTheRouteThroughABendAtASafeSpeed) {
  ClosedLoop loop;
  double worst_lateral = 0;
  for (int i = 0; i < 150; ++i) {
    loop.step(12);
    worst_lateral = std::max(worst_lateral, loop.lateral);
  }
  EXPECT_GT(loop.s, 70);  // well into the bend
  EXPECT_LT(worst_lateral, 0.5);
  // sqrt(2 m/s^2 * 40 m) = 8.9 m/s in the bend, below the limit of 12.
  EXPECT_GT(loop.observation.ego.speed, 6);
  EXPECT_LT(loop.observation.ego.speed, 9.5);
}

TEST(PluginDriverExample, StopsBeforeTheLineOfARedLightAndGoesOnGreen) {
  ClosedLoop loop;
  const double line = 25;
  loop.observation.light = SCENFUZZ_LIGHT_RED;
  for (int i = 0; i < 200; ++i) {
    loop.observation.light_distance = line - loop.s;
    loop.step(10);
  }
  const double front = loop.observation.ego.x + 0.5 * car_config().vehicle.length;
  EXPECT_LT(loop.observation.ego.speed, 0.05);
  EXPECT_LE(front, line);
  EXPECT_GT(front, line - 3);
  loop.observation.light = SCENFUZZ_LIGHT_GREEN;
  for (int i = 0; i < 30; ++i) loop.step(10);
  EXPECT_GT(loop.observation.ego.x + 0.5 * car_config().vehicle.length, line);
}

TEST(PluginDriverExample, FollowsASlowerCarAtATwoSecondGap) {
  ClosedLoop loop;
  loop.road.straight = 1e4;
  loop.observation.ego.speed = 12;
  loop.observation.object_count = 1;
  scenfuzz_object& lead = loop.observation.objects[0];
  lead = {3, SCENFUZZ_OBJECT_VEHICLE, 30, 0, 0, 6, 4.7, 1.85};
  const double length = car_config().vehicle.length;
  double closest = kInfinity;
  for (int i = 0; i < 400; ++i) {
    lead.x += 6 * 0.1;
    loop.step(15);
    const double gap = lead.x - loop.observation.ego.x - 0.5 * (length + lead.length);
    closest = std::min(closest, gap);
  }
  const double gap = lead.x - loop.observation.ego.x - 0.5 * (length + lead.length);
  EXPECT_GT(closest, 2);
  EXPECT_NEAR(loop.observation.ego.speed, 6, 0.3);
  EXPECT_NEAR(gap, 2 + 2 * 6, 2);
}

TEST(PluginDriver, ReportsACrashWithSignalAndStepAndTheNextDriverStillWorks) {
  const std::string library = test_plugin("crashing");
  PluginDriver driver(options_for(library), car_config());
  const pid_t child = driver.child_process();
  scenfuzz_observation observation = open_road(0);
  EXPECT_EQ(driver.step(observation).acceleration, 1);
  EXPECT_EQ(driver.step(observation).acceleration, 1);
  try {
    driver.step(observation);
    FAIL() << "the crash went unnoticed";
  } catch (const EgoPluginError& error) {
    EXPECT_THAT(error.what(), HasSubstr("'" + library + "'"));
    EXPECT_THAT(error.what(), HasSubstr("crashed (SIGSEGV) at step 3"));
    EXPECT_EQ(error.kind(), EgoFailureKind::crash);
    EXPECT_EQ(error.signal(), "SIGSEGV");
    EXPECT_EQ(error.step(), 3);
  }
  EXPECT_TRUE(reaped(child));
  EXPECT_THROW(driver.step(observation), EgoPluginError);  // spent

  PluginDriver next(options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN), car_config());
  set_straight_route(observation, 10);
  EXPECT_GT(next.step(observation).acceleration, 0);
}

TEST(PluginDriver, KillsAPluginThatDoesNotAnswerInTime) {
  const std::string library = test_plugin("hanging");
  PluginDriver driver(options_for(library, 0.3), car_config());
  const pid_t child = driver.child_process();
  try {
    driver.step(open_road(0));
    FAIL() << "the hang went unnoticed";
  } catch (const EgoPluginError& error) {
    EXPECT_THAT(error.what(), HasSubstr("'" + library + "' did not answer within 0.3 s at step 1"));
    EXPECT_THAT(error.what(), HasSubstr("(killed)"));
    EXPECT_EQ(error.kind(), EgoFailureKind::hang);
    EXPECT_EQ(error.signal(), "") << "killed by the host, not by a signal of its own";
    EXPECT_EQ(error.step(), 1);
  }
  EXPECT_TRUE(reaped(child));
  EXPECT_EQ(driver.child_process(), -1);
}

TEST(PluginDriver, ReportsTheErrorCodeAPluginReturns) {
  const std::string library = test_plugin("failing");
  PluginDriver driver(options_for(library), car_config());
  EXPECT_NO_THROW(driver.step(open_road(0)));
  try {
    driver.step(open_road(0));
    FAIL() << "the error went unnoticed";
  } catch (const EgoPluginError& error) {
    EXPECT_THAT(error.what(), HasSubstr("'" + library + "' returned error 7 at step 2"));
    EXPECT_EQ(error.kind(), EgoFailureKind::error);
    EXPECT_EQ(error.step(), 2);
  }
  try {
    driver.step(open_road(0));
    FAIL() << "a spent driver answered";
  } catch (const EgoPluginError& error) {
    EXPECT_THAT(error.what(), HasSubstr("returned error 7 at step 2")) << "the same error again";
    EXPECT_EQ(error.kind(), EgoFailureKind::error);
    EXPECT_EQ(error.step(), 2);
  }
}

TEST(PluginDriver, NamesTheLibraryAndTheSymbolItLacks) {
  const std::string library = test_plugin("missing_symbol");
  try {
    PluginDriver driver(options_for(library), car_config());
    FAIL() << "a plugin without scenfuzz_ego_step was accepted";
  } catch (const EgoPluginError& error) {
    EXPECT_THAT(error.what(), HasSubstr("'" + library + "' lacks symbol scenfuzz_ego_step"));
    EXPECT_EQ(error.kind(), EgoFailureKind::error);
    EXPECT_EQ(error.step(), 0);
  }
}

TEST(PluginDriver, NamesALibraryThatCannotBeLoaded) {
  const std::string library = test_plugin("no_such_plugin");
  try {
    PluginDriver driver(options_for(library), car_config());
    FAIL() << "a missing library was accepted";
  } catch (const EgoPluginError& error) {
    EXPECT_THAT(error.what(), HasSubstr("cannot load ego plugin '" + library + "'"));
    EXPECT_THAT(error.what(), HasSubstr("No such file"));
    EXPECT_EQ(error.kind(), EgoFailureKind::error);
    EXPECT_EQ(error.step(), 0);
  }
}

TEST(PluginDriver, RejectsAnEmptyLibraryAndNonPositiveTimeouts) {
  EXPECT_THROW(PluginDriver(options_for(""), car_config()), std::invalid_argument);
  EXPECT_THROW(PluginDriver(options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN, 0), car_config()),
               std::invalid_argument);
}

TEST(PluginDriver, LeavesNoZombiesBehind) {
  std::vector<pid_t> children;
  for (int i = 0; i < 20; ++i) {
    PluginDriver driver(options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN), car_config());
    children.push_back(driver.child_process());
    driver.step(open_road(0));
  }
  for (const pid_t child : children) EXPECT_TRUE(reaped(child)) << "child " << child;
}

TEST(PluginDriver, DriversOnSeveralThreadsAtOnceEachSeeTheirOwnOutcome) {
  // Each child closes the descriptors it inherits, so a crash is seen at once even while other
  // threads fork children of their own.
  std::vector<std::string> outcomes(4);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < outcomes.size(); ++t) {
    threads.emplace_back([&outcomes, t] {
      for (int round = 0; round < 5; ++round) {
        const bool crash = (t + static_cast<size_t>(round)) % 2 == 0;
        PluginDriver driver(
            options_for(crash ? test_plugin("crashing") : SCENFUZZ_EXAMPLE_EGO_PLUGIN),
            car_config());
        try {
          for (int i = 0; i < 4; ++i) driver.step(open_road(0));
          outcomes[t] += crash ? "missed crash;" : "";
        } catch (const EgoPluginError& error) {
          const bool saw_crash =
              std::string(error.what()).find("(SIGSEGV) at step 3") != std::string::npos;
          outcomes[t] += crash && saw_crash ? "" : std::string(error.what()) + ";";
        }
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (const std::string& outcome : outcomes) EXPECT_EQ(outcome, "");
}

TEST(PluginDriver, MovesWithItsChild) {
  PluginDriver first(options_for(SCENFUZZ_EXAMPLE_EGO_PLUGIN), car_config());
  const pid_t child = first.child_process();
  PluginDriver second(std::move(first));
  EXPECT_EQ(second.child_process(), child);
  scenfuzz_observation observation = open_road(0);
  set_straight_route(observation, 10);
  EXPECT_GT(second.step(observation).acceleration, 0);

  PluginDriver third(options_for(test_plugin("failing")), car_config());
  const pid_t replaced = third.child_process();
  third = std::move(second);
  EXPECT_TRUE(reaped(replaced));
  EXPECT_EQ(third.child_process(), child);
  EXPECT_EQ(third.steps(), 1);
}

}  // namespace
}  // namespace scenfuzz
