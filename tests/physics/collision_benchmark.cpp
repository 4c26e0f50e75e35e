// Collision figures: one simulation step of the collision world (every car moved, then
// find_contacts) for 10 and 30 cars in multi-lane traffic, with narrowphase checks per second;
// and the cost per call of the footprint signed distance against FCL's distance.
#include <benchmark/benchmark.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "physics/collision/collision_world.hpp"
#include "physics/collision/footprint.hpp"

namespace scenfuzz {
namespace {

constexpr double pi = std::numbers::pi;
const BodyGeometry kCar{BodyShape::box, 4.6, 1.9, 1.5};
constexpr double kLaneWidth = 3.5;
constexpr double kCarSpacing = 10;  // metres of road per car in a lane
constexpr int kLanes = 5;
constexpr double kStep = 0.05;  // seconds
constexpr std::size_t kRecordedSteps = 400;

// Cars in kLanes lanes, weaving across their lane. In crashing traffic each car has its own
// speed, so faster cars drive into slower ones and neighbours side-swipe now and then: a stress
// test of the narrowphase. In flowing traffic each lane keeps one speed and nothing touches, as
// in most simulation steps. The road wraps around, keeping the traffic as dense all the time.
// Poses are computed beforehand, so the timing is the collision world's alone.
std::vector<std::vector<MapPose>> traffic(std::size_t cars, bool crashing) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> speed(8, 20), weave_phase(0, 2 * pi);
  const std::size_t cars_per_lane = (cars + kLanes - 1) / kLanes;
  const double road_length = kCarSpacing * static_cast<double>(cars_per_lane);
  std::vector<std::vector<MapPose>> steps(kRecordedSteps, std::vector<MapPose>(cars));
  for (std::size_t car = 0; car < cars; ++car) {
    const double start = kCarSpacing * static_cast<double>(car / kLanes);
    const double lane_centre = kLaneWidth * static_cast<double>(car % kLanes);
    const double lane_speed = 10 + static_cast<double>(car % kLanes);
    const double car_speed = crashing ? speed(random) : lane_speed;
    const double phase = weave_phase(random);
    for (std::size_t step = 0; step < kRecordedSteps; ++step) {
      const double time = kStep * static_cast<double>(step);
      const double x = std::fmod(start + car_speed * time, road_length);
      const double weave = 0.4 * std::sin(0.8 * time + phase);
      const double heading = 0.05 * std::cos(0.8 * time + phase);
      steps[step][car] = {{x, lane_centre + weave}, heading};
    }
  }
  return steps;
}

void BM_CollisionStep(benchmark::State& state) {
  const auto cars = static_cast<std::size_t>(state.range(0));
  const bool crashing = state.range(1) == 1;
  const std::vector<std::vector<MapPose>> steps = traffic(cars, crashing);
  CollisionWorld world;
  for (const MapPose& pose : steps.front()) world.add_body(kCar, pose, false);
  std::size_t step = 0, contacts = 0;
  for (auto _ : state) {
    const std::vector<MapPose>& poses = steps[step];
    for (std::size_t car = 0; car < cars; ++car)
      world.set_pose(static_cast<BodyId>(car), poses[car]);
    contacts += world.find_contacts().size();
    step = (step + 1) % steps.size();
  }
  const auto iterations = static_cast<double>(state.iterations());
  state.counters["checks/s"] = benchmark::Counter(static_cast<double>(world.narrowphase_checks()),
                                                  benchmark::Counter::kIsRate);
  state.counters["checks/step"] = static_cast<double>(world.narrowphase_checks()) / iterations;
  state.counters["contacts/step"] = static_cast<double>(contacts) / iterations;
  state.SetLabel(crashing ? "crashing traffic" : "flowing traffic");
}
BENCHMARK(BM_CollisionStep)
    ->ArgsProduct({{10, 30}, {0, 1}})
    ->ArgNames({"cars", "crashing"})
    ->Unit(benchmark::kMicrosecond);

// Random car pairs, separated or overlapping as asked.
std::vector<std::pair<Footprint, Footprint>> car_pairs(bool overlapping) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> position(-8, 8), heading(-pi, pi);
  std::vector<std::pair<Footprint, Footprint>> pairs;
  while (pairs.size() < 1024) {
    const Footprint a{{0, 0}, heading(random), 2.3, 0.95, false};
    const Footprint b{{position(random), position(random)}, heading(random), 2.3, 0.95, false};
    if ((signed_distance(a, b) < 0) == overlapping) pairs.emplace_back(a, b);
  }
  return pairs;
}

void BM_SignedDistance(benchmark::State& state) {
  const auto pairs = car_pairs(state.range(0) == 1);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(signed_distance(pairs[i].first, pairs[i].second));
    i = (i + 1) % pairs.size();
  }
  state.SetLabel(state.range(0) == 1 ? "overlapping cars" : "separated cars");
}
BENCHMARK(BM_SignedDistance)->Arg(0)->Arg(1);

void BM_SignedDistanceCarPedestrian(benchmark::State& state) {
  const Footprint car{{0, 0}, 0.4, 2.3, 0.95, false};
  std::mt19937_64 random(9);
  std::uniform_real_distribution<double> position(-8, 8);
  std::vector<Footprint> pedestrians;
  for (int i = 0; i < 1024; ++i)
    pedestrians.push_back({{position(random), position(random)}, 0, 0.3, 0.3, true});
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(signed_distance(car, pedestrians[i]));
    i = (i + 1) % pedestrians.size();
  }
}
BENCHMARK(BM_SignedDistanceCarPedestrian);

fcl::Transform3d standing(const Footprint& body) {
  fcl::Transform3d transform = fcl::Transform3d::Identity();
  transform.translation() = fcl::Vector3d(body.centre.x, body.centre.y, kCar.height / 2);
  transform.linear() = Eigen::AngleAxisd(body.heading, fcl::Vector3d::UnitZ()).toRotationMatrix();
  return transform;
}

// FCL's own GJK (GST_INDEP), as CollisionWorld::distance uses it for separated bodies.
void BM_FclDistance(benchmark::State& state) {
  const auto pairs = car_pairs(false);
  auto box = std::make_shared<fcl::Boxd>(kCar.length, kCar.width, kCar.height);
  std::vector<std::pair<fcl::CollisionObjectd, fcl::CollisionObjectd>> objects;
  for (const auto& [a, b] : pairs)
    objects.emplace_back(fcl::CollisionObjectd(box, standing(a)),
                         fcl::CollisionObjectd(box, standing(b)));
  fcl::DistanceRequestd request;
  request.gjk_solver_type = fcl::GST_INDEP;
  std::size_t i = 0;
  for (auto _ : state) {
    fcl::DistanceResultd result;
    benchmark::DoNotOptimize(fcl::distance(&objects[i].first, &objects[i].second, request, result));
    i = (i + 1) % objects.size();
  }
  state.SetLabel("separated cars");
}
BENCHMARK(BM_FclDistance);

// The whole CollisionWorld::distance: footprints, then FCL's distance or collision test.
void BM_WorldDistance(benchmark::State& state) {
  const auto pairs = car_pairs(state.range(0) == 1);
  CollisionWorld world;
  for (const auto& [a, b] : pairs) {
    world.add_body(kCar, {a.centre, a.heading}, false);
    world.add_body(kCar, {b.centre, b.heading}, false);
  }
  BodyId first = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(world.distance(first, first + 1));
    first = (first + 2) % static_cast<BodyId>(world.body_count());
  }
  state.SetLabel(state.range(0) == 1 ? "overlapping cars" : "separated cars");
}
BENCHMARK(BM_WorldDistance)->Arg(0)->Arg(1);

// The path planner's validity check against 12 static obstacles on a 100 m map.
void BM_TouchesStatic(benchmark::State& state) {
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> position(0, 100), heading(-pi, pi), size(1, 4);
  CollisionWorld world;
  for (int i = 0; i < 12; ++i) {
    const double diameter = size(random);
    world.add_body({i % 2 == 0 ? BodyShape::box : BodyShape::cylinder, diameter, diameter, 1.5},
                   {{position(random), position(random)}, heading(random)}, true);
  }
  std::vector<MapPose> queries;
  for (int i = 0; i < 1024; ++i)
    queries.push_back({{position(random), position(random)}, heading(random)});
  std::size_t i = 0, touching = 0;
  for (auto _ : state) {
    touching += world.touches_static(kCar, queries[i]) ? 1 : 0;
    i = (i + 1) % queries.size();
  }
  state.counters["touching"] =
      static_cast<double>(touching) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_TouchesStatic);

}  // namespace
}  // namespace scenfuzz

BENCHMARK_MAIN();
