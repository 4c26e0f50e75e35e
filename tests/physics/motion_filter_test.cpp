// MotionFilter skips the sine and cosine of standing objects, tracks pedestrians and vehicles (not
// obstacles) and reuses its storage: the smoothed speeds must be those of the plain computation,
// bit for bit; and how much the smoothing reduces independent noise.
#include "physics/ego/motion_filter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <vector>

#include "physics/map/map_point.hpp"

namespace scenfuzz {
namespace {

// The filter as it was: every velocity from its heading's cosine and sine.
struct PlainFilter {
  std::map<ActorId, std::pair<double, double>> tracks;
  void update(const std::vector<WorldObject>& objects, double weight) {
    std::map<ActorId, std::pair<double, double>> next;
    for (const WorldObject& object : objects) {
      double velocity = object.reversing ? -object.speed : object.speed;
      double vx = velocity * std::cos(object.heading), vy = velocity * std::sin(object.heading);
      if (auto old = tracks.find(object.id); old != tracks.end()) {
        vx = old->second.first + weight * (vx - old->second.first);
        vy = old->second.second + weight * (vy - old->second.second);
      }
      next[object.id] = {vx, vy};
    }
    tracks = std::move(next);
  }
  double speed(ActorId id) const {
    auto found = tracks.find(id);
    return found == tracks.end() ? 0 : std::hypot(found->second.first, found->second.second);
  }
};

TEST(MotionFilter, SmoothedSpeedsAreThePlainComputationsBitForBit) {
  std::mt19937_64 random(31);
  std::uniform_real_distribution<double> unit(0, 1);
  MotionFilter filter(0.5);
  PlainFilter plain;
  const double dt = 0.05;
  int standing = 0;
  for (int step = 0; step < 2000; ++step) {
    std::vector<WorldObject> objects;
    for (ActorId id = 1; id <= 12; ++id) {
      if (unit(random) < 0.1) continue;  // unseen this step: forgotten
      WorldObject object;
      object.id = id;
      // Ids 1 to 8 pedestrians, 9 and 10 vehicles, the rest obstacles (passed over).
      object.kind = id <= 8    ? TraceActorKind::pedestrian
                    : id <= 10 ? TraceActorKind::vehicle
                               : TraceActorKind::obstacle;
      object.heading = (unit(random) - 0.5) * 7;
      // Perception clamps noisy speeds at zero: standing objects often read exactly 0.
      object.speed = unit(random) < 0.4 ? 0.0 : 10 * unit(random);
      object.reversing = unit(random) < 0.2;
      standing += object.speed == 0;
      objects.push_back(object);
    }
    filter.update(objects, dt);
    plain.update(objects, std::clamp(dt / 0.5, 0.0, 1.0));
    for (ActorId id = 0; id <= 13; ++id)
      ASSERT_EQ(filter.speed(id), id <= 10 ? plain.speed(id) : 0.0)
          << "step " << step << " id " << id;
  }
  EXPECT_GT(standing, 5000) << "standing objects were tried";
}

TEST(MotionFilter, AStandingObjectWithANonFiniteHeadingStaysAsThePlainComputationHasIt) {
  MotionFilter filter(0.5);
  WorldObject object;
  object.id = 3;
  object.kind = TraceActorKind::pedestrian;
  object.speed = 0;
  object.heading = std::nan("");
  filter.update(std::vector<WorldObject>{object}, 0.05);
  EXPECT_TRUE(std::isnan(filter.speed(3)));  // 0 * cos(NaN), as before
}

TEST(MotionFilter, PedestriansAndVehiclesAreTrackedObstaclesNot) {
  MotionFilter filter(0.5);
  WorldObject walker, car, rock;
  walker.id = 1;
  walker.kind = TraceActorKind::pedestrian;
  walker.speed = 1.2;
  car.id = 2;
  car.kind = TraceActorKind::vehicle;
  car.speed = 10;
  car.heading = 0.5;
  rock.id = 3;
  rock.kind = TraceActorKind::obstacle;
  filter.update(std::vector<WorldObject>{walker, car, rock}, 0.05);
  EXPECT_EQ(filter.speed(1), std::hypot(1.2 * std::cos(0.0), 1.2 * std::sin(0.0)));
  ASSERT_TRUE(filter.velocity(2));
  EXPECT_EQ(filter.velocity(2)->x, 10 * std::cos(0.5));
  EXPECT_EQ(filter.velocity(2)->y, 10 * std::sin(0.5));
  EXPECT_FALSE(filter.velocity(3));
  EXPECT_EQ(filter.speed(3), 0.0);
}

TEST(MotionFilter, NoiseReductionIsTheSmoothedWhiteNoisesStandardDeviationRatio) {
  MotionFilter filter(0.5);
  std::mt19937_64 random(7);
  std::normal_distribution<double> noise(0, 1);
  const double dt = 0.05;
  WorldObject car;
  car.id = 1;
  car.kind = TraceActorKind::vehicle;
  double sum = 0, squares = 0;
  const int steps = 200000;
  for (int step = 0; step < steps; ++step) {
    car.speed = 10;
    car.heading = 0.1 * noise(random);  // the y component: 10 sin(heading), about 1 m/s of noise
    filter.update(std::vector<WorldObject>{car}, dt);
    const double y = filter.velocity(1)->y;
    sum += y;
    squares += y * y;
  }
  const double deviation = std::sqrt(squares / steps - (sum / steps) * (sum / steps));
  const double raw = 10 * std::sqrt((1 - std::exp(-2 * 0.01)) / 2);  // sd of 10 sin(N(0, 0.1))
  EXPECT_NEAR(deviation / raw, filter.noise_reduction(dt), 0.01);
  EXPECT_EQ(filter.noise_reduction(0), 1.0);
}

TEST(MotionFilter, AVehiclesHeadingIsAveragedAcrossPiAndAPedestrianHasNone) {
  MotionFilter filter(0.5);
  WorldObject car;
  car.id = 1;
  car.kind = TraceActorKind::vehicle;
  car.speed = 10;
  WorldObject walker;
  walker.id = 2;
  walker.kind = TraceActorKind::pedestrian;
  for (int step = 0; step < 100; ++step) {
    // About pi, off by 0.06 rad either way in turn: the angle jumps between +pi and -pi.
    car.heading = angle_difference(std::numbers::pi + (step % 2 == 0 ? 0.06 : -0.06), 0);
    filter.update(std::vector<WorldObject>{car, walker}, 0.05);
  }
  EXPECT_NEAR(std::abs(*filter.heading(1)), std::numbers::pi, 0.01);
  EXPECT_FALSE(filter.heading(2)) << "a pedestrian has no heading worth smoothing";
  EXPECT_FALSE(filter.heading(3)) << "unknown";
}

}  // namespace
}  // namespace scenfuzz
