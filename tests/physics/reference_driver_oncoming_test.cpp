// The reference driver and an oncoming truck passing close by in the other lane of the built-in
// two-way straight (east_0 at y = -1.75, west_0 at y = 1.75): perception's heading noise, a few
// degrees on a truck at 13 m/s, is a lateral speed that seemed to carry it into the ego's path
// for a step, and the ego braked in full for that step (phantom braking, in rain or fog); the same
// noise swings a long truck's corners sideways. A truck that really swerves into the ego's lane
// must still make it brake before it gets there.
#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "physics/actors/actor_class.hpp"
#include "physics/ego/reference_driver.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/map_source.hpp"

namespace scenfuzz {
namespace {

constexpr double kStep = 0.05;            // s, the simulation's step
constexpr double kHeadingNoise = 0.06;    // rad, as perception's in rain and fog
constexpr double kTruckHalfWidth = 1.25;  // m

struct OncomingFixture {
  RoadMap map = load_map("straight?lanes=1&lane_width=3.5", MapSearchPath{});
  LaneRoute route = *find_route(map, LanePosition{*map.find_lane("east_0"), 100, 0},
                                LanePosition{*map.find_lane("east_0"), 400, 0});
  RouteTracker tracker{map, route, {}, 13.9};
  const ActorClass& car = actor_class(ActorCategory::car);
  KinematicState ego;
  KinematicState truck;

  OncomingFixture(double ego_speed, double truck_ahead, double truck_y) {
    ego.x = 100;
    ego.y = -1.75;
    ego.speed = ego_speed;
    truck.x = ego.x + truck_ahead;
    truck.y = truck_y;
    truck.heading = std::numbers::pi;
    truck.speed = 13;
  }

  // The truck as perceived at step `k`: its heading off by the noise's size, alternately either
  // way (a step's error towards the ego's path every other step).
  WorldObject perceived(int k) const {
    WorldObject seen;
    seen.id = 1;
    seen.x = truck.x;
    seen.y = truck.y;
    seen.heading = truck.heading + (k % 2 == 0 ? kHeadingNoise : -kHeadingNoise);
    seen.speed = truck.speed;
    seen.length = 8;
    seen.width = 2 * kTruckHalfWidth;
    return seen;
  }

  // Moves both on by a step, the ego along its lane at the driver's acceleration.
  void advance(double acceleration) {
    ego.speed = std::max(0.0, ego.speed + acceleration * kStep);
    ego.x += ego.speed * kStep;
    truck.x += truck.speed * std::cos(truck.heading) * kStep;
    truck.y += truck.speed * std::sin(truck.heading) * kStep;
  }
};

PerceptionSettings noisy_sensing() {
  PerceptionSettings sensing;
  sensing.heading_noise = kHeadingNoise;
  return sensing;
}

TEST(ReferenceDriverOncoming, ATruckPassingCloseInItsLaneWithHeadingNoiseIsNoReasonToBrake) {
  // The truck keeps its lane, 5 cm inside the centre line, 0.4 m outside the ego's corridor.
  OncomingFixture f(0.5, 60, 1.3);
  ReferenceDriver driver(f.map, f.tracker, f.car, true, DriverSettings{}, noisy_sensing());
  for (int k = 0; f.truck.x > f.ego.x - 20; ++k) {
    f.tracker.update({f.ego.x, f.ego.y});
    std::vector<WorldObject> objects{f.perceived(k)};
    const VehicleControl control = driver.step({k * kStep, f.ego, objects, {}});
    ASSERT_NE(driver.last_reason(), DriverReason::emergency)
        << "full braking at " << k * kStep << " s, the truck " << f.truck.x - f.ego.x << " m ahead";
    ASSERT_GT(control.acceleration, -1.0) << "at " << k * kStep << " s";
    f.advance(control.acceleration);
  }
}

TEST(ReferenceDriverOncoming, HeadingNoiseSwingingAPassingTrucksCornersIsNoReasonToBrake) {
  // 0.15 m outside the ego's corridor (a narrow road): 3.4 degrees of heading either way swings
  // the 8 m truck's front corner 0.24 m towards the ego, into the corridor, on every step.
  const ActorClass& car = actor_class(ActorCategory::car);
  const double corridor_edge = -1.75 + car.width / 2 + 0.4;
  OncomingFixture f(8, 60, corridor_edge + 0.15 + kTruckHalfWidth);
  ReferenceDriver driver(f.map, f.tracker, f.car, true, DriverSettings{}, noisy_sensing());
  for (int k = 0; f.truck.x > f.ego.x - 20; ++k) {
    f.tracker.update({f.ego.x, f.ego.y});
    std::vector<WorldObject> objects{f.perceived(k)};
    const VehicleControl control = driver.step({k * kStep, f.ego, objects, {}});
    ASSERT_GT(control.acceleration, -1.0)
        << "braked at " << k * kStep << " s, the truck " << f.truck.x - f.ego.x << " m ahead";
    f.advance(control.acceleration);
  }
}

TEST(ReferenceDriverOncoming, ATruckSwervingIntoTheEgosLaneMakesItBrakeBeforeItGetsThere) {
  OncomingFixture f(8, 40, 1.75);
  ReferenceDriver driver(f.map, f.tracker, f.car, true, DriverSettings{}, noisy_sensing());
  // The ego's corridor: its half width and the driver's margin beside it.
  const double corridor_edge = f.ego.y + f.car.width / 2 + 0.4;
  bool braked = false;
  for (int k = 0; f.truck.y - kTruckHalfWidth > corridor_edge; ++k) {
    // 14 m ahead (bumper to bumper) it turns 9 degrees towards the ego's lane: 2 m/s across.
    if (f.truck.x - f.ego.x < 14 + 4 + f.car.length / 2) f.truck.heading = std::numbers::pi + 0.15;
    f.tracker.update({f.ego.x, f.ego.y});
    std::vector<WorldObject> objects{f.perceived(k)};
    const VehicleControl control = driver.step({k * kStep, f.ego, objects, {}});
    braked = braked || control.acceleration <= -DriverSettings{}.comfortable_deceleration;
    f.advance(control.acceleration);
  }
  EXPECT_TRUE(braked) << "the truck reached the ego's corridor without the ego braking";
}

}  // namespace
}  // namespace scenfuzz
