// The reference driver passing a bus parked over the line of the next lane (built-in one-way
// straight: east_1 at y = -1.75, east_0 at y = -5.25): perception's heading noise swung the 12 m
// bus's corners a few centimetres into the ego's corridor for single steps, and each brought a
// step of hard braking (parked_van_pulls_out, in rain). A bus that really stands in the corridor
// must still hold the ego back, whatever the noise on its position.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "physics/actors/actor_class.hpp"
#include "physics/ego/reference_driver.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/map_source.hpp"

namespace scenfuzz {
namespace {

constexpr double kStep = 0.05;          // s, the simulation's step
constexpr double kPositionNoise = 0.2;  // m, as perception's in rain at night
constexpr double kBusHalfWidth = 1.25;  // m
constexpr double kNoiseOffset = 0.4;    // m, two standard deviations, either way in turn
constexpr double kHeadingNoise = 0.06;  // rad, as perception's in rain at night

struct ParkedBusFixture {
  RoadMap map = load_map("straight?lanes=2&two_way=0", MapSearchPath{});
  LaneRoute route = *find_route(map, LanePosition{*map.find_lane("east_1"), 50, 0},
                                LanePosition{*map.find_lane("east_1"), 400, 0});
  RouteTracker tracker{map, route, {}, 13.9};
  const ActorClass& car = actor_class(ActorCategory::car);
  KinematicState ego;
  double bus_x = 0;
  double bus_y = 0;
  // The edge of the ego's corridor on the bus's side: its half width and the driver's margin.
  double corridor_edge = 0;

  // The bus `inside` metres into the corridor (negative: outside it), `ahead` metres ahead.
  ParkedBusFixture(double ahead, double inside) {
    ego.x = 50;
    ego.y = -1.75;
    ego.speed = 10;
    corridor_edge = ego.y - car.width / 2 - 0.4;
    bus_x = ego.x + ahead;
    bus_y = corridor_edge + inside - kBusHalfWidth;
  }

  // The bus as perceived at step `k`: off sideways by the noise's offset, or turned by the
  // heading noise, either way in turn.
  WorldObject perceived(int k, bool turned = false) const {
    WorldObject seen;
    seen.id = 1;
    seen.x = bus_x;
    const double sign = k % 2 == 0 ? 1 : -1;
    seen.y = bus_y + (turned ? 0 : sign * kNoiseOffset);
    seen.heading = turned ? sign * kHeadingNoise : 0;
    seen.speed = 0;
    seen.length = 12;
    seen.width = 2 * kBusHalfWidth;
    return seen;
  }

  void advance(double acceleration) {
    ego.speed = std::max(0.0, ego.speed + acceleration * kStep);
    ego.x += ego.speed * kStep;
  }
};

PerceptionSettings noisy_sensing() {
  PerceptionSettings sensing;
  sensing.position_noise = kPositionNoise;
  sensing.heading_noise = kHeadingNoise;
  return sensing;
}

// Drives the ego past the bus; the strongest braking on the way (m/s^2, negative).
double hardest_braking_passing(ParkedBusFixture& f, bool turned) {
  ReferenceDriver driver(f.map, f.tracker, f.car, true, DriverSettings{}, noisy_sensing());
  double hardest = 0;
  for (int k = 0; f.bus_x > f.ego.x - 10; ++k) {
    f.tracker.update({f.ego.x, f.ego.y});
    std::vector<WorldObject> objects{f.perceived(k, turned)};
    const VehicleControl control = driver.step({k * kStep, f.ego, objects, {}});
    hardest = std::min(hardest, control.acceleration);
    f.advance(control.acceleration);
  }
  return hardest;
}

TEST(ReferenceDriverParkedBus, HeadingNoiseOnABusJustOutsideTheCorridorIsNoReasonToBrake) {
  // 0.2 m outside: every other step the noise swings its corner 0.36 m, 0.16 m inside.
  ParkedBusFixture f(60, -0.2);
  EXPECT_GT(hardest_braking_passing(f, true), -1.0);
}

TEST(ReferenceDriverParkedBus, ABusStandingInTheCorridorHoldsTheEgoBack) {
  // 0.3 m inside, less than the 0.6 m (three standard deviations) one step's reading needs.
  ParkedBusFixture f(40, 0.3);
  ReferenceDriver driver(f.map, f.tracker, f.car, true, DriverSettings{}, noisy_sensing());
  bool held = false;
  for (int k = 0; k < 200 && !held; ++k) {
    f.tracker.update({f.ego.x, f.ego.y});
    std::vector<WorldObject> objects{f.perceived(k)};
    const VehicleControl control = driver.step({k * kStep, f.ego, objects, {}});
    held = driver.last_reason() == DriverReason::lead;
    f.advance(control.acceleration);
  }
  EXPECT_TRUE(held) << "the ego never followed the bus standing in its corridor";
}

}  // namespace
}  // namespace scenfuzz
