// The perception model: range and field of view, weather and darkness, latency, coasting,
// determinism and noise statistics.
#include "physics/ego/perception.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

namespace scenfuzz {
namespace {

constexpr double kDt = 0.05;
constexpr double kPi = std::numbers::pi;

WorldObject vehicle_at(double x, double y, ActorId id = 1) {
  return {.id = id, .kind = TraceActorKind::vehicle, .x = x, .y = y, .length = 4.7, .width = 1.85};
}

WorldObject pedestrian_at(double x, double y, ActorId id = 2) {
  return {
      .id = id, .kind = TraceActorKind::pedestrian, .x = x, .y = y, .length = 0.6, .width = 0.6};
}

std::optional<WorldObject> find(const std::vector<WorldObject>& seen, ActorId id) {
  for (const WorldObject& object : seen) {
    if (object.id == id) return object;
  }
  return std::nullopt;
}

// Steps the model over a static scene and counts the steps on which `id` was detected afresh
// (coast_time 0, so a miss is not hidden by a coasted track).
int detections(PerceptionSettings settings, std::span<const WorldObject> truth, ActorId id,
               int steps, std::uint64_t seed = 1, KinematicState ego = {}) {
  settings.coast_time = 0;
  Perception perception(settings, seed, kDt);
  int count = 0;
  for (int i = 0; i < steps; ++i) count += find(perception.observe(ego, truth), id) ? 1 : 0;
  return count;
}

TEST(PerceptionConditions, DarknessFollowsTheTimeOfDay) {
  EXPECT_EQ(darkness_at(0), 1);
  EXPECT_EQ(darkness_at(3 * 3600), 1);
  EXPECT_EQ(darkness_at(5 * 3600), 1);
  EXPECT_NEAR(darkness_at(6 * 3600), 0.5, 1e-12);
  EXPECT_EQ(darkness_at(7 * 3600), 0);
  EXPECT_EQ(darkness_at(12 * 3600), 0);
  EXPECT_EQ(darkness_at(18 * 3600), 0);
  EXPECT_NEAR(darkness_at(19.5 * 3600), 0.75, 1e-12);
  EXPECT_EQ(darkness_at(20 * 3600), 1);
  EXPECT_EQ(darkness_at(23.9 * 3600), 1);
  EXPECT_EQ(darkness_at((24 + 12) * 3600), 0);  // wraps past midnight
  EXPECT_THROW(darkness_at(std::nan("")), std::invalid_argument);
}

TEST(PerceptionConditions, ClearConditionsChangeNothing) {
  const PerceptionSettings clear;
  const PerceptionSettings same = degraded(clear, {});
  EXPECT_EQ(same.vehicle_range, clear.vehicle_range);
  EXPECT_EQ(same.pedestrian_range, clear.pedestrian_range);
  EXPECT_EQ(same.position_noise, clear.position_noise);
  EXPECT_EQ(same.miss_probability, clear.miss_probability);
}

TEST(PerceptionConditions, EachConditionWorsensAndTheyCombine) {
  const PerceptionSettings clear;
  for (const Conditions conditions : {Conditions{.fog = 0.5}, Conditions{.rain = 1},
                                      Conditions{.snow = 1}, Conditions{.darkness = 1}}) {
    const PerceptionSettings worse = degraded(clear, conditions);
    EXPECT_LT(worse.vehicle_range, clear.vehicle_range);
    EXPECT_LT(worse.pedestrian_range, clear.pedestrian_range);
    EXPECT_GT(worse.position_noise, clear.position_noise);
    EXPECT_GT(worse.miss_probability, clear.miss_probability);
  }
  const PerceptionSettings fog = degraded(clear, {.fog = 1});
  EXPECT_NEAR(fog.vehicle_range, 0.15 * clear.vehicle_range, 1e-9);
  const PerceptionSettings fog_and_rain = degraded(clear, {.fog = 1, .rain = 1});
  EXPECT_NEAR(fog_and_rain.vehicle_range, 0.15 * 0.7 * clear.vehicle_range, 1e-9);
  const PerceptionSettings everything = degraded(clear, {1, 1, 1, 1});
  EXPECT_EQ(everything.pedestrian_range, 10);  // the floor
  EXPECT_EQ(everything.vehicle_range, 10);
  EXPECT_LT(everything.miss_probability, 1);
}

TEST(PerceptionConditions, DarknessShortensPedestrianRangeMoreThanVehicleRange) {
  const PerceptionSettings clear;
  const PerceptionSettings night = degraded(clear, {.darkness = 1});
  EXPECT_LT(night.pedestrian_range / clear.pedestrian_range,
            night.vehicle_range / clear.vehicle_range - 0.3);
}

TEST(PerceptionConditions, OutOfRangeConditionsAreRejected) {
  EXPECT_THROW(degraded({}, {.fog = 1.5}), std::invalid_argument);
  EXPECT_THROW(degraded({}, {.rain = -0.1}), std::invalid_argument);
  EXPECT_THROW(degraded({}, {.snow = std::nan("")}), std::invalid_argument);
  EXPECT_THROW(Perception(PerceptionSettings{.vehicle_range = -1}, 1, kDt), std::invalid_argument);
}

TEST(PerceptionRange, FogHidesAnObjectAt60Metres) {
  const std::vector<WorldObject> truth{vehicle_at(60, 0)};
  EXPECT_GE(detections({}, truth, 1, 400), 370);  // about 3.5 % misses
  EXPECT_EQ(detections(degraded({}, {.fog = 1}), truth, 1, 400), 0);
}

TEST(PerceptionRange, NothingBeyondTheRange) {
  const std::vector<WorldObject> truth{vehicle_at(151, 0), pedestrian_at(0, 81)};
  EXPECT_EQ(detections({}, truth, 1, 200), 0);
  EXPECT_EQ(detections({}, truth, 2, 200), 0);
}

TEST(PerceptionRange, MissesGrowTowardsTheEdgeOfTheRange) {
  const std::vector<WorldObject> truth{vehicle_at(20, 0, 1), vehicle_at(0, 140, 2)};
  EXPECT_GT(detections({}, truth, 1, 1000), detections({}, truth, 2, 1000) + 200);
}

TEST(PerceptionRange, DarknessHidesPedestriansBeforeVehicles) {
  // Both at 45 m: within the pedestrian range by day (80 m) but not at night (32 m), while the
  // vehicle range at night (120 m) still covers them.
  const std::vector<WorldObject> truth{vehicle_at(45, 0, 1), pedestrian_at(0, 45, 2)};
  const PerceptionSettings night = degraded({}, {.darkness = 1});
  EXPECT_GE(detections({}, truth, 2, 400), 300);
  EXPECT_EQ(detections(night, truth, 2, 400), 0);
  EXPECT_GE(detections(night, truth, 1, 400), 330);  // about 8 % misses at night
}

TEST(PerceptionRange, FieldOfViewHidesWhatIsBehind) {
  // A long range and no misses: every object in view is detected on every step.
  const PerceptionSettings forward{
      .vehicle_range = 5000, .field_of_view = 120 * kPi / 180, .miss_probability = 0};
  const KinematicState ego{.x = 100, .y = 50, .heading = kPi / 2};  // facing north
  const std::vector<WorldObject> truth{vehicle_at(100, 80, 1), vehicle_at(100, 20, 2),
                                       vehicle_at(125, 60, 3), vehicle_at(110, 70, 4)};
  EXPECT_EQ(detections(forward, truth, 1, 100, 1, ego), 100);  // ahead
  EXPECT_EQ(detections(forward, truth, 2, 100, 1, ego), 0);    // behind
  EXPECT_EQ(detections(forward, truth, 3, 100, 1, ego), 0);    // 68 deg right of the heading
  EXPECT_EQ(detections(forward, truth, 4, 100, 1, ego), 100);  // 27 deg right
  EXPECT_EQ(detections({.vehicle_range = 5000, .miss_probability = 0}, truth, 2, 100, 1, ego),
            100);  // all round
}

TEST(PerceptionTiming, PerceivedPositionLagsBySpeedTimesLatency) {
  // A long range so that the distance never causes a miss.
  const PerceptionSettings settings{.vehicle_range = 5000,
                                    .position_noise = 0,
                                    .heading_noise = 0,
                                    .speed_noise = 0,
                                    .latency = 0.2,
                                    .miss_probability = 0};
  Perception perception(settings, 7, kDt);
  const double speed = 10;
  for (int i = 0; i < 50; ++i) {
    WorldObject car = vehicle_at(20 + speed * i * kDt, 3);
    car.speed = speed;
    const auto seen = find(perception.observe({}, std::span(&car, 1)), 1);
    ASSERT_TRUE(seen.has_value());
    // Before latency has passed, the car is seen where it started.
    const double lag = std::min(i * kDt, settings.latency) * speed;
    EXPECT_NEAR(seen->x, car.x - lag, 1e-9) << "step " << i;
    EXPECT_NEAR(seen->y, 3, 1e-12);
  }
}

TEST(PerceptionTiming, CoastingBridgesAMissAndEndsAfterCoastTime) {
  // A long range so that the distance never causes a miss.
  const PerceptionSettings settings{.vehicle_range = 5000,
                                    .position_noise = 0,
                                    .heading_noise = 0,
                                    .speed_noise = 0,
                                    .latency = 0,
                                    .miss_probability = 0,
                                    .coast_time = 0.3};
  Perception perception(settings, 3, kDt);
  WorldObject car = vehicle_at(30, 0);
  car.speed = 4;
  std::vector<WorldObject> truth{car};
  ASSERT_TRUE(find(perception.observe({}, truth), 1));
  // The car leaves the range: it is kept, moving on at its last speed, for 0.3 s (6 steps) and
  // gone on the 7th.
  truth[0].x = 6000;
  for (int i = 1; i <= 6; ++i) {
    const auto seen = find(perception.observe({}, truth), 1);
    ASSERT_TRUE(seen.has_value()) << "step " << i;
    EXPECT_NEAR(seen->x, 30 + 4 * i * kDt, 1e-9);
  }
  EXPECT_FALSE(find(perception.observe({}, truth), 1));
  // A single miss is bridged: back in range, detected afresh at its true place.
  truth[0].x = 40;
  ASSERT_TRUE(find(perception.observe({}, truth), 1));
  truth[0].x = 6000;
  EXPECT_TRUE(find(perception.observe({}, truth), 1));
  truth[0].x = 41;
  const auto again = find(perception.observe({}, truth), 1);
  ASSERT_TRUE(again.has_value());
  EXPECT_NEAR(again->x, 41, 1e-12);
}

TEST(PerceptionTiming, OutputIsSortedByIdAndLeavesOutTheEgo) {
  Perception perception({.vehicle_range = 5000, .pedestrian_range = 5000, .miss_probability = 0}, 1,
                        kDt);
  const std::vector<WorldObject> truth{vehicle_at(30, 0, 5),
                                       pedestrian_at(10, 0, 2),
                                       {.id = 0, .kind = TraceActorKind::ego},
                                       vehicle_at(-20, 0, 3)};
  const auto& seen = perception.observe({}, truth);
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_EQ(seen[0].id, 2u);
  EXPECT_EQ(seen[1].id, 3u);
  EXPECT_EQ(seen[2].id, 5u);
  EXPECT_EQ(seen[0].kind, TraceActorKind::pedestrian);
}

std::vector<std::vector<WorldObject>> run(std::uint64_t seed) {
  const PerceptionSettings settings = degraded({}, {.rain = 0.5, .darkness = 0.3});
  Perception perception(settings, seed, kDt);
  std::vector<std::vector<WorldObject>> outputs;
  for (int i = 0; i < 200; ++i) {
    const double t = i * kDt;
    std::vector<WorldObject> truth{vehicle_at(40 + 8 * t, 0, 1), pedestrian_at(30, -5 + t, 2),
                                   vehicle_at(95 - 5 * t, 3.5, 4)};
    outputs.push_back(perception.observe({.x = 12 * t, .speed = 12}, truth));
  }
  return outputs;
}

bool same(const std::vector<std::vector<WorldObject>>& a,
          const std::vector<std::vector<WorldObject>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].size() != b[i].size()) return false;
    for (std::size_t j = 0; j < a[i].size(); ++j) {
      const WorldObject &p = a[i][j], &q = b[i][j];
      if (p.id != q.id || p.x != q.x || p.y != q.y || p.heading != q.heading ||
          p.speed != q.speed) {
        return false;
      }
    }
  }
  return true;
}

TEST(PerceptionDeterminism, SameSeedSameOutputsOtherSeedOtherNoise) {
  const auto first = run(42);
  EXPECT_TRUE(same(first, run(42)));
  EXPECT_FALSE(same(first, run(43)));
}

TEST(PerceptionNoise, StatisticsMatchTheSettings) {
  const PerceptionSettings settings{.vehicle_range = 5000,
                                    .position_noise = 0.3,
                                    .heading_noise = 0.05,
                                    .speed_noise = 0.2,
                                    .latency = 0,
                                    .miss_probability = 0};
  Perception perception(settings, 2024, kDt);
  WorldObject car = vehicle_at(25, 10);
  car.heading = 1.0;
  car.speed = 8;
  const int samples = 5000;
  double sum[4] = {}, squares[4] = {};
  for (int i = 0; i < samples; ++i) {
    const auto seen = find(perception.observe({}, std::span(&car, 1)), 1);
    ASSERT_TRUE(seen.has_value());
    const double errors[4] = {seen->x - car.x, seen->y - car.y, seen->heading - car.heading,
                              seen->speed - car.speed};
    for (int k = 0; k < 4; ++k) {
      sum[k] += errors[k];
      squares[k] += errors[k] * errors[k];
    }
  }
  const double expected[4] = {0.3, 0.3, 0.05, 0.2};
  for (int k = 0; k < 4; ++k) {
    const double mean = sum[k] / samples;
    const double deviation = std::sqrt(squares[k] / samples - mean * mean);
    EXPECT_NEAR(mean, 0, 4 * expected[k] / std::sqrt(samples)) << "component " << k;
    EXPECT_NEAR(deviation, expected[k], 0.2 * expected[k]) << "component " << k;
  }
}

}  // namespace
}  // namespace scenfuzz
