// Accident reconstruction on traces built by hand: the score is negative exactly when every
// described collision happened between the named pair, with the named parts, in order and near
// the place, and where it is positive it is the distance the search still has to go.
#include "oracle/collision_reconstruction.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "tests/oracle/trace_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::empty_trace;
using test::still_actor;

constexpr double kTruckLength = 8.0, kTruckWidth = 2.5;
constexpr double kCarLength = 4.6, kCarWidth = 1.85;
constexpr double kEnd = 2.0;  // s: the last sample, where the hand-made contacts happen
constexpr double kNorth = std::numbers::pi / 2;

// The left side of car1 (standing at the origin, facing north) is the line x = -kCarWidth / 2.
constexpr double kCarLeftX = -kCarWidth / 2;

// The ego far away, truck1 driving east so that its front reaches `gap` metres short of car1's
// left side at kEnd, car1 standing at the origin facing north. No contact recorded yet.
Trace crossing(double gap = 0) {
  Trace trace = empty_trace(21, 0.1);
  trace.actors.push_back(still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, kCarLength,
                                     kCarWidth, 100, 50));
  trace.actors.push_back(still_actor(trace, "truck1", TraceActorKind::vehicle, BodyShape::box,
                                     kTruckLength, kTruckWidth, 0, 0));
  TraceActor& truck = trace.actors.back();
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    truck.x[i] = kCarLeftX - gap - kTruckLength / 2 - 10 * (kEnd - trace.time[i]);
    truck.speed[i] = 10;
  }
  trace.actors.push_back(still_actor(trace, "car1", TraceActorKind::vehicle, BodyShape::box,
                                     kCarLength, kCarWidth, 0, 0, kNorth));
  return trace;
}

// Records the first contact of `striker` with `victim`, as the simulation does: lower id first.
void touch(Trace& trace, const std::string& striker, BodySide striker_side,
           const std::string& victim, BodySide victim_side, MapPoint point, double time = kEnd) {
  const ActorId s = *trace.find_actor(striker), v = *trace.find_actor(victim);
  Collision c{time, s, v, point, striker_side, victim_side};
  if (s > v) c = {time, v, s, point, victim_side, striker_side};
  trace.collisions.push_back(c);
}

Position place(double x, double y, Frame frame = Frame::enu) {
  Position p;
  p.kind = PositionKind::coordinate;
  p.frame = frame;
  p.x = constant_value(x);
  p.y = constant_value(y);
  return p;
}

ExpectedCollision described(std::string striker, VehiclePart striker_part, std::string victim,
                            VehiclePart victim_part, std::optional<Position> where = {}) {
  ExpectedCollision e;
  e.striker = std::move(striker);
  e.striker_part = striker_part;
  e.victim = std::move(victim);
  e.victim_part = victim_part;
  e.position = std::move(where);
  return e;
}

// ACTOR = truck1, front; VICTIM = car1, leftside.
ExpectedCollision t_bone(std::optional<Position> where = {}) {
  return described("truck1", VehiclePart::front, "car1", VehiclePart::left_side, std::move(where));
}

// truck1's front in the middle of car1's left side.
Trace t_bone_trace() {
  Trace trace = crossing();
  touch(trace, "truck1", BodySide::front, "car1", BodySide::left, {kCarLeftX, 0});
  return trace;
}

ReconstructionScore score(const Trace& trace, const std::vector<ExpectedCollision>& expected,
                          std::vector<double> parameters = {}) {
  return score_reconstruction(trace, expected, parameters);
}

TEST(CollisionReconstructionTest, TheDescribedCollisionIsNegativeByItsLeastSlack) {
  const ReconstructionScore s = score(t_bone_trace(), {t_bone(place(kCarLeftX + 1, 0))});
  ASSERT_EQ(s.collisions.size(), 1u);
  const CollisionCheck& c = s.collisions[0];
  EXPECT_TRUE(c.happened);
  EXPECT_TRUE(c.satisfied);
  EXPECT_EQ(c.problem, "");
  EXPECT_EQ(c.striker_side, BodySide::front);
  EXPECT_EQ(c.victim_side, BodySide::left);
  EXPECT_DOUBLE_EQ(c.time, kEnd);
  // Slacks: the contact is 1.25 m from the truck's front corners (the tightest), 2.3 m from the
  // car's, 4 m inside the place's tolerance.
  EXPECT_NEAR(c.robustness, -(kReconstructionMargin + kTruckWidth / 2), 1e-9);
  EXPECT_EQ(s.robustness, c.robustness);
}

TEST(CollisionReconstructionTest, AContactInACornerStillCountsAsMet) {
  Trace trace = crossing();
  touch(trace, "truck1", BodySide::front, "car1", BodySide::left, {kCarLeftX, kTruckWidth / 2});
  const ReconstructionScore s = score(trace, {t_bone()});
  EXPECT_TRUE(s.collisions[0].satisfied);
  EXPECT_NEAR(s.robustness, -kReconstructionMargin, 1e-9);
}

TEST(CollisionReconstructionTest, AWrongVictimSideIsPositiveAndShrinksTowardsTheNamedSide) {
  Trace trace = crossing();
  touch(trace, "truck1", BodySide::front, "car1", BodySide::rear, {0, -kCarLength / 2});
  const ReconstructionScore middle = score(trace, {t_bone()});
  EXPECT_FALSE(middle.collisions[0].satisfied);
  EXPECT_TRUE(middle.collisions[0].happened);
  EXPECT_EQ(middle.collisions[0].problem,
            "truck1 hit car1 with its front on car1's rear, not its left side");
  EXPECT_NEAR(middle.robustness, kCarWidth / 2 + kReconstructionMargin, 1e-9);

  trace.collisions[0].point = {-0.5, -kCarLength / 2};  // nearer the left rear corner
  const ReconstructionScore nearer = score(trace, {t_bone()});
  EXPECT_GT(nearer.robustness, kReconstructionMargin);
  EXPECT_LT(nearer.robustness, middle.robustness);
  EXPECT_NEAR(nearer.robustness, std::abs(kCarLeftX + 0.5) + kReconstructionMargin, 1e-9);
}

TEST(CollisionReconstructionTest, AWrongStrikerSideIsPositive) {
  const ExpectedCollision rear_first =
      described("truck1", VehiclePart::rear, "car1", VehiclePart::left_side);
  const ReconstructionScore s = score(t_bone_trace(), {rear_first});
  EXPECT_EQ(s.collisions[0].problem,
            "truck1 hit car1 with its front, not its rear, on car1's left side");
  // The contact is a truck's length from its rear.
  EXPECT_NEAR(s.robustness, kTruckLength + kReconstructionMargin, 1e-9);
}

TEST(CollisionReconstructionTest, EitherOrderOfIdsMatchesByName) {
  // car1 has the higher id: the trace lists truck1 first, the description car1 as the striker.
  const ExpectedCollision car_strikes =
      described("car1", VehiclePart::left_side, "truck1", VehiclePart::front);
  const ReconstructionScore s = score(t_bone_trace(), {car_strikes});
  EXPECT_TRUE(s.collisions[0].satisfied);
  EXPECT_EQ(s.collisions[0].striker_side, BodySide::left);
  EXPECT_EQ(s.collisions[0].victim_side, BodySide::front);
  EXPECT_LT(s.robustness, 0);

  const ExpectedCollision swapped =
      described("car1", VehiclePart::front, "truck1", VehiclePart::left_side);
  EXPECT_GT(score(t_bone_trace(), {swapped}).robustness, 0);
}

// truck1 hits car1 at `t_bone_time`, car1 hits car2 (just north of it) at `push_time`.
Trace chain(double t_bone_time, double push_time) {
  Trace trace = t_bone_trace();
  trace.collisions[0].time = t_bone_time;
  trace.actors.push_back(still_actor(trace, "car2", TraceActorKind::vehicle, BodyShape::box,
                                     kCarLength, kCarWidth, 0, kCarLength, kNorth));
  touch(trace, "car1", BodySide::front, "car2", BodySide::rear, {0, kCarLength / 2}, push_time);
  return trace;
}

const ExpectedCollision kPush = described("car1", VehiclePart::front, "car2", VehiclePart::rear);

TEST(CollisionReconstructionTest, CollisionsInTheDescribedOrderAreNegative) {
  EXPECT_LT(score(chain(1.0, 1.5), {t_bone(), kPush}).robustness, 0);
  EXPECT_LT(score(chain(1.0, 1.0), {t_bone(), kPush}).robustness, 0);  // at the same instant
}

TEST(CollisionReconstructionTest, AWrongOrderIsPositiveByTheTimeDifference) {
  const ReconstructionScore s = score(chain(1.5, 1.0), {t_bone(), kPush});
  EXPECT_TRUE(s.collisions[0].satisfied);
  EXPECT_FALSE(s.collisions[1].satisfied);
  EXPECT_NEAR(s.robustness, 0.5 * kOrderSpeed + kReconstructionMargin, 1e-9);
  EXPECT_EQ(s.collisions[1].problem,
            "car1 hit car2 at 1 s, before the collision described before it (at 1.5 s)");
  EXPECT_LT(score(chain(1.2, 1.0), {t_bone(), kPush}).robustness, s.robustness);
}

TEST(CollisionReconstructionTest, NoContactIsPositiveAndDecreasesAsTheBodiesApproach) {
  double previous = std::numeric_limits<double>::infinity();
  for (double gap : {6.0, 3.0, 1.0, 0.2}) {
    const ReconstructionScore s = score(crossing(gap), {t_bone()});
    EXPECT_FALSE(s.collisions[0].happened);
    // The truck's front edge is parallel to the car's left side, `gap` away at the end.
    EXPECT_NEAR(s.collisions[0].closest_approach, gap, 1e-9);
    EXPECT_NEAR(s.robustness, gap + kReconstructionMargin, 1e-9);
    EXPECT_LT(s.robustness, previous);
    previous = s.robustness;
  }
  EXPECT_EQ(score(crossing(3), {t_bone()}).collisions[0].problem,
            "truck1 never touched car1 (closest approach of truck1's front to car1's left side: "
            "3 m)");
}

TEST(CollisionReconstructionTest, TheClosestApproachIsThatOfTheNamedParts) {
  const ExpectedCollision rear_first =
      described("truck1", VehiclePart::rear, "car1", VehiclePart::unknown);
  EXPECT_NEAR(score(crossing(1), {rear_first}).collisions[0].closest_approach, 1 + kTruckLength,
              1e-9);
  const ExpectedCollision on_the_right =
      described("truck1", VehiclePart::front, "car1", VehiclePart::right_side);
  EXPECT_NEAR(score(crossing(1), {on_the_right}).collisions[0].closest_approach, 1 + kCarWidth,
              1e-9);
}

TEST(CollisionReconstructionTest, APlaceBeyondTheToleranceIsPositive) {
  const ReconstructionScore far = score(t_bone_trace(), {t_bone(place(kCarLeftX + 6, 0))});
  EXPECT_FALSE(far.collisions[0].satisfied);
  EXPECT_NEAR(far.robustness, 6 - kPlaceTolerance + kReconstructionMargin, 1e-9);
  EXPECT_THAT(far.collisions[0].problem,
              testing::StartsWith("truck1 hit car1 6 m from the described place ("));
  EXPECT_THAT(far.collisions[0].problem, testing::EndsWith("), beyond the 5 m tolerance"));

  EXPECT_LT(score(t_bone_trace(), {t_bone(place(kCarLeftX, 4.9))}).robustness, 0);
  EXPECT_GT(score(t_bone_trace(), {t_bone(place(kCarLeftX, 5.0))}).robustness, 0);
}

TEST(CollisionReconstructionTest, APlaceIsEvaluatedWithTheParameters) {
  Position where = place(0, 0);
  where.x = parameter_value(0);
  EXPECT_LT(score(t_bone_trace(), {t_bone(where)}, {kCarLeftX + 4}).robustness, 0);
  EXPECT_GT(score(t_bone_trace(), {t_bone(where)}, {kCarLeftX + 7}).robustness, 0);
}

TEST(CollisionReconstructionTest, AnImuPlaceIsRelativeToTheEgosInitialPose) {
  // The ego starts at (100, 50) facing east: IMU y is forward (east), x to its right (south).
  const double forward = kCarLeftX - 100, right = 50;
  EXPECT_LT(score(t_bone_trace(), {t_bone(place(right, forward, Frame::imu))}).robustness, 0);
  EXPECT_GT(score(t_bone_trace(), {t_bone(place(right - 6, forward, Frame::imu))}).robustness, 0);
}

TEST(CollisionReconstructionTest, UnknownPartsMatchAnySide) {
  const ExpectedCollision anyhow =
      described("truck1", VehiclePart::unknown, "car1", VehiclePart::unknown);
  const ExpectedCollision any_striker =
      described("truck1", VehiclePart::unknown, "car1", VehiclePart::left_side);
  for (BodySide truck_side : {BodySide::front, BodySide::rear, BodySide::left, BodySide::right}) {
    for (BodySide car_side : {BodySide::front, BodySide::rear, BodySide::left, BodySide::right}) {
      Trace trace = crossing();
      touch(trace, "truck1", truck_side, "car1", car_side, {kCarLeftX, 0});
      const ReconstructionScore s = score(trace, {anyhow});
      EXPECT_TRUE(s.collisions[0].satisfied);
      EXPECT_NEAR(s.robustness, -kReconstructionMargin, 1e-9);
      EXPECT_EQ(score(trace, {any_striker}).collisions[0].satisfied, car_side == BodySide::left);
    }
  }
}

// car1 facing east, its front `gap` metres short of a tree (a cylinder 0.6 m across) at (5, 0).
Trace tree_ahead(double gap) {
  Trace trace = empty_trace(21, 0.1);
  trace.actors.push_back(still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, kCarLength,
                                     kCarWidth, 100, 50));
  trace.actors.push_back(still_actor(trace, "car1", TraceActorKind::vehicle, BodyShape::box,
                                     kCarLength, kCarWidth, 5 - 0.3 - gap - kCarLength / 2, 0));
  trace.actors.push_back(
      still_actor(trace, "tree", TraceActorKind::obstacle, BodyShape::cylinder, 0.6, 0.6, 5, 0));
  return trace;
}

TEST(CollisionReconstructionTest, ATreeCanBeTheVictim) {
  const ExpectedCollision into_tree =
      described("car1", VehiclePart::front, "tree", VehiclePart::unknown);
  Trace hit = tree_ahead(0);
  touch(hit, "car1", BodySide::front, "tree", BodySide::rear, {4.7, 0});
  EXPECT_TRUE(score(hit, {into_tree}).collisions[0].satisfied);
  EXPECT_LT(score(hit, {into_tree}).robustness, 0);

  const ExpectedCollision reversing_into_tree =
      described("car1", VehiclePart::rear, "tree", VehiclePart::unknown);
  EXPECT_NEAR(score(hit, {reversing_into_tree}).robustness, kCarLength + kReconstructionMargin,
              1e-9);

  // Not touched: the gap from the car's front edge to the trunk's circle.
  EXPECT_NEAR(score(tree_ahead(2.5), {into_tree}).robustness, 2.5 + kReconstructionMargin, 1e-9);
  EXPECT_GT(score(tree_ahead(2.5), {into_tree}).robustness,
            score(tree_ahead(1.0), {into_tree}).robustness);
}

TEST(CollisionReconstructionTest, ANamedSideOfATreeIsAQuarterOfItsRim) {
  Trace hit = tree_ahead(0);
  touch(hit, "car1", BodySide::front, "tree", BodySide::rear, {4.7, 0});
  const ExpectedCollision tree_front =
      described("car1", VehiclePart::front, "tree", VehiclePart::front);
  // The nearest point of the front quarter is its end, 45 degrees from the tree's heading.
  const double r = 0.3, end = r * std::cos(std::numbers::pi / 4);
  EXPECT_NEAR(score(hit, {tree_front}).robustness,
              std::hypot(5 + end - 4.7, end) + kReconstructionMargin, 1e-9);
}

TEST(CollisionReconstructionTest, TwoCollisionsWhereOnlyTheFirstHappenedArePositive) {
  Trace trace = t_bone_trace();
  trace.actors.push_back(still_actor(trace, "car2", TraceActorKind::vehicle, BodyShape::box,
                                     kCarLength, kCarWidth, 0, kCarLength + 2, kNorth));
  const ReconstructionScore s = score(trace, {t_bone(), kPush});
  EXPECT_TRUE(s.collisions[0].satisfied);
  EXPECT_FALSE(s.collisions[1].happened);
  // car1's front edge stays 2 m short of car2's rear edge.
  EXPECT_NEAR(s.collisions[1].closest_approach, 2, 1e-9);
  EXPECT_NEAR(s.robustness, 2 + kReconstructionMargin, 1e-9);
}

TEST(CollisionReconstructionTest, ACollisionNotDescribedBeforeTheLastDescribedOneIsPositive) {
  // Only the t-bone is described; car1 also hits car2, before it or after it.
  const ReconstructionScore before = score(chain(1.5, 1.0), {t_bone()});
  ASSERT_EQ(before.undescribed.size(), 1u);
  EXPECT_EQ(before.undescribed[0].first, "car1");
  EXPECT_EQ(before.undescribed[0].second, "car2");
  EXPECT_NEAR(before.robustness, 0.5 * kOrderSpeed + kReconstructionMargin, 1e-9);
  // The later it comes, the nearer the run is to the accident described.
  EXPECT_LT(score(chain(1.5, 1.4), {t_bone()}).robustness, before.robustness);
  // After the accident described, what else happened is not the description's.
  const ReconstructionScore after = score(chain(1.0, 1.5), {t_bone()});
  EXPECT_TRUE(after.undescribed.empty());
  EXPECT_LT(after.robustness, 0);
}

TEST(CollisionReconstructionTest, NoDescribedCollisionIsVacuouslyMet) {
  const ReconstructionScore s = score(crossing(3), {});
  EXPECT_TRUE(s.collisions.empty());
  EXPECT_EQ(s.robustness, -std::numeric_limits<double>::infinity());
}

TEST(CollisionReconstructionTest, NamesAndPlacesTheTranslationRejectsThrow) {
  const Trace trace = t_bone_trace();
  EXPECT_THROW(score(trace, {described("bus", VehiclePart::front, "car1", VehiclePart::rear)}),
               std::invalid_argument);
  EXPECT_THROW(score(trace, {described("car1", VehiclePart::front, "car1", VehiclePart::rear)}),
               std::invalid_argument);
  EXPECT_THROW(score(trace, {t_bone(place(8.5, 47.4, Frame::wgs84))}), std::invalid_argument);
}

TEST(CollisionReconstructionTest, PartsMapToBodySides) {
  EXPECT_EQ(body_side_of(VehiclePart::front), BodySide::front);
  EXPECT_EQ(body_side_of(VehiclePart::rear), BodySide::rear);
  EXPECT_EQ(body_side_of(VehiclePart::left_side), BodySide::left);
  EXPECT_EQ(body_side_of(VehiclePart::right_side), BodySide::right);
  EXPECT_EQ(body_side_of(VehiclePart::unknown), std::nullopt);
}

}  // namespace
}  // namespace scenfuzz
