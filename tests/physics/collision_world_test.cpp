// The collision world on the crashes a scenario produces: which pairs touch, where, and on which
// side of each body; distances between bodies; and the static-obstacle check of path planning.
#include "physics/collision/collision_world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace scenfuzz {
namespace {

constexpr double pi = std::numbers::pi;
const BodyGeometry kCar{BodyShape::box, 4.6, 1.9, 1.5};
const BodyGeometry kPedestrian{BodyShape::cylinder, 0.6, 0.6, 1.8};

MapPose at(double x, double y, double heading = 0) { return {{x, y}, heading}; }

// The one contact of a two-body world, which the test expects to exist.
Contact only_contact(CollisionWorld& world) {
  const std::vector<Contact>& contacts = world.find_contacts();
  EXPECT_EQ(contacts.size(), 1u);
  return contacts.empty() ? Contact{} : contacts.front();
}

TEST(CollisionWorld, HeadOnHitsBothFronts) {
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), false);
  world.add_body(kCar, at(4.5, 0.2, pi), false);
  const Contact contact = only_contact(world);
  EXPECT_EQ(contact.first, 0u);
  EXPECT_EQ(contact.second, 1u);
  EXPECT_EQ(contact.first_side, BodySide::front);
  EXPECT_EQ(contact.second_side, BodySide::front);
  EXPECT_NEAR(contact.point.x, 2.25, 1e-9) << "the middle of the 0.1 m overlap";
  EXPECT_NEAR(contact.point.y, 0.1, 1e-9) << "the middle of the lateral overlap [-0.75, 0.95]";
}

TEST(CollisionWorld, RearEndHitsStrikerFrontAndVictimRear) {
  CollisionWorld world;
  const BodyId victim = world.add_body(kCar, at(0, 0), false);
  const BodyId striker = world.add_body(kCar, at(-4.5, 0), false);
  const Contact contact = only_contact(world);
  ASSERT_EQ(contact.first, victim);
  ASSERT_EQ(contact.second, striker);
  EXPECT_EQ(contact.first_side, BodySide::rear);
  EXPECT_EQ(contact.second_side, BodySide::front);
}

TEST(CollisionWorld, SideSwipeHitsLeftOfOneAndRightOfTheOther) {
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), false);
  world.add_body(kCar, at(1.0, 1.85), false);  // in the lane to the left, slightly ahead
  const Contact contact = only_contact(world);
  EXPECT_EQ(contact.first_side, BodySide::left);
  EXPECT_EQ(contact.second_side, BodySide::right);
}

TEST(CollisionWorld, TBoneHitsFrontAndSide) {
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), false);
  world.add_body(kCar, at(3.2, 0, pi / 2), false);    // crossing northwards: we hit its left
  world.add_body(kCar, at(3.2, 20, -pi / 2), false);  // crossing southwards, elsewhere
  world.add_body(kCar, at(0, 20), false);             // hits that one's right
  const std::vector<Contact>& contacts = world.find_contacts();
  ASSERT_EQ(contacts.size(), 2u);
  EXPECT_EQ(contacts[0].first, 0u);
  EXPECT_EQ(contacts[0].second, 1u);
  EXPECT_EQ(contacts[0].first_side, BodySide::front);
  EXPECT_EQ(contacts[0].second_side, BodySide::left);
  EXPECT_EQ(contacts[1].first, 2u);
  EXPECT_EQ(contacts[1].second, 3u);
  EXPECT_EQ(contacts[1].first_side, BodySide::right);
  EXPECT_EQ(contacts[1].second_side, BodySide::front);
}

TEST(CollisionWorld, CarHitsCrossingPedestrian) {
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), false);
  world.add_body(kPedestrian, at(2.5, 0.3, pi / 2), false);  // walking north across its path
  const Contact contact = only_contact(world);
  EXPECT_EQ(contact.first_side, BodySide::front);
  EXPECT_EQ(contact.second_side, BodySide::left) << "the car comes from the walker's left";
  EXPECT_NEAR(contact.point.y, 0.3, 1e-9);
  EXPECT_GT(contact.point.x, 2.19);
  EXPECT_LT(contact.point.x, 2.3);
}

TEST(CollisionWorld, ContactPointIsExactAtUtmCoordinates) {
  // Apollo maps are in UTM: coordinates in the millions. The same crash there and at the origin
  // must give the same contact point relative to the bodies.
  const double east = 553000, north = 4181719;
  CollisionWorld near_origin, in_utm;
  near_origin.add_body(kCar, at(0, 0), false);
  near_origin.add_body(kPedestrian, at(2.5, 0.3, pi / 2), false);
  in_utm.add_body(kCar, at(east, north), false);
  in_utm.add_body(kPedestrian, at(east + 2.5, north + 0.3, pi / 2), false);
  const Contact expected = only_contact(near_origin);
  const Contact actual = only_contact(in_utm);
  EXPECT_NEAR(actual.point.x - east, expected.point.x, 1e-6);
  EXPECT_NEAR(actual.point.y - north, expected.point.y, 1e-6);
  EXPECT_EQ(actual.second_side, expected.second_side);
}

TEST(CollisionWorld, CarHitsEveryStaticObstacleShape) {
  for (BodyShape shape :
       {BodyShape::box, BodyShape::sphere, BodyShape::cone, BodyShape::cylinder}) {
    SCOPED_TRACE(static_cast<int>(shape));
    const BodyGeometry obstacle{shape, 1.0, 1.0, 1.0};
    CollisionWorld world;
    world.add_body(kCar, at(0, 0), false);
    // 0.1 m into the car's front (a cone only near the ground, where it is widest).
    world.add_body(obstacle, at(2.7, 0), true);
    const Contact contact = only_contact(world);
    EXPECT_EQ(contact.first_side, BodySide::front);
    EXPECT_EQ(contact.second_side, BodySide::rear);

    CollisionWorld apart;
    apart.add_body(kCar, at(0, 0), false);
    apart.add_body(obstacle, at(2.81, 0), true);
    EXPECT_TRUE(apart.find_contacts().empty()) << "1 cm apart";
    EXPECT_NEAR(apart.distance(0, 1), 0.01, 1e-5);
  }
}

TEST(CollisionWorld, ConeStandsOnItsBase) {
  // A 3 m cone 0.1 m into the car's front at the ground; upside down, it would miss the car.
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), false);
  world.add_body({BodyShape::cone, 1, 1, 3}, at(2.7, 0), true);
  EXPECT_EQ(world.find_contacts().size(), 1u);
  EXPECT_TRUE(world.touches_static(kCar, at(0, 0)));
}

TEST(CollisionWorld, NoContactOneCentimetreApart) {
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), false);
  world.add_body(kCar, at(4.61, 0), false);
  world.add_body(kCar, at(0, 1.91), false);
  world.add_body(kPedestrian, at(-2.3 - 0.31, 0), false);
  world.add_body(kCar, at(4.61 + 2.3 + 0.95 + 0.01, 0, pi / 2), false);
  EXPECT_TRUE(world.find_contacts().empty());
  EXPECT_NEAR(world.distance(0, 1), 0.01, 1e-9);
  EXPECT_NEAR(world.distance(0, 2), 0.01, 1e-9);
  EXPECT_NEAR(world.distance(0, 3), 0.01, 1e-5);
  EXPECT_NEAR(world.distance(1, 4), 0.01, 1e-9) << "exactly at right angles";
}

TEST(CollisionWorld, FindsEveryPairNotJustTheFirst) {
  CollisionWorld world;
  for (int i = 0; i < 5; ++i) world.add_body(kCar, at(0.5 * i, 0.1 * i), false);
  world.add_body(kCar, at(50, 0), false);
  const std::vector<Contact>& contacts = world.find_contacts();
  std::vector<std::pair<BodyId, BodyId>> pairs;
  for (const Contact& contact : contacts) pairs.emplace_back(contact.first, contact.second);
  const std::vector<std::pair<BodyId, BodyId>> expected = {{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2},
                                                           {1, 3}, {1, 4}, {2, 3}, {2, 4}, {3, 4}};
  EXPECT_EQ(pairs, expected);
}

TEST(CollisionWorld, StaticBodiesNeverCollideWithEachOther) {
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), true);
  world.add_body(kCar, at(1, 0), true);
  world.add_body(kCar, at(30, 0), false);
  EXPECT_TRUE(world.find_contacts().empty());
  world.add_body(kCar, at(1.5, 0.5), false);
  const std::vector<Contact>& contacts = world.find_contacts();
  ASSERT_EQ(contacts.size(), 2u);
  EXPECT_EQ(contacts[0].first, 0u);
  EXPECT_EQ(contacts[0].second, 3u);
  EXPECT_EQ(contacts[1].first, 1u);
  EXPECT_EQ(contacts[1].second, 3u);
}

TEST(CollisionWorld, ContactsFollowTheBodiesAsTheyMove) {
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), false);
  const BodyId other = world.add_body(kCar, at(20, 0, pi), false);
  EXPECT_TRUE(world.find_contacts().empty());
  world.set_pose(other, at(4.4, 0, pi));
  EXPECT_EQ(world.find_contacts().size(), 1u) << "the broadphase saw the move";
  world.set_pose(other, at(4.7, 0, pi));
  EXPECT_TRUE(world.find_contacts().empty());
  EXPECT_NEAR(world.footprint(other).centre.x, 4.7, 1e-12);
}

TEST(CollisionWorld, OnlyBroadphaseCandidatesReachTheNarrowphase) {
  CollisionWorld world;
  for (int i = 0; i < 10; ++i) world.add_body(kCar, at(10.0 * i, 0), false);
  world.find_contacts();
  EXPECT_EQ(world.narrowphase_checks(), 0u) << "no bounding boxes overlap";
  world.set_pose(1, at(4.0, 0));
  world.find_contacts();
  EXPECT_EQ(world.narrowphase_checks(), 1u);
}

TEST(CollisionWorld, IgnoredPairsAreNeitherTestedNorReported) {
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), false);
  world.add_body(kCar, at(1, 0), false);
  world.add_body(kCar, at(2, 0.5), false);
  ASSERT_EQ(world.find_contacts().size(), 3u);
  world.ignore_pair(1, 0);  // either order
  const std::uint64_t checks = world.narrowphase_checks();
  const std::vector<Contact>& contacts = world.find_contacts();
  ASSERT_EQ(contacts.size(), 2u);
  EXPECT_EQ(std::make_pair(contacts[0].first, contacts[0].second), std::make_pair(0u, 2u));
  EXPECT_EQ(std::make_pair(contacts[1].first, contacts[1].second), std::make_pair(1u, 2u));
  EXPECT_EQ(world.narrowphase_checks() - checks, 2u) << "the ignored pair costs no narrowphase";
}

// The broadphase keeps the footprint bounds of a body that turns in place up to date (a car
// across the road reaches 2.3 m sideways, along it 0.95 m).
TEST(CollisionWorld, TurningInPlaceUpdatesTheBroadphase) {
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), false);
  world.add_body(kCar, at(0, 3), false);
  EXPECT_TRUE(world.find_contacts().empty());
  world.set_pose(0, at(0, 0, pi / 2));
  EXPECT_EQ(world.find_contacts().size(), 1u);
  world.set_pose(0, at(0, 0, 0));
  EXPECT_TRUE(world.find_contacts().empty());
}

// Cars strewn at random, moved at random for many steps: the contacts are exactly the pairs
// whose solids overlap, as brute force over every pair says (FCL's distance is 0 for them).
TEST(CollisionWorld, ContactsMatchBruteForceInRandomTraffic) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(0, 40), angle(-pi, pi), nudge(-1.5, 1.5);
  CollisionWorld world;
  std::vector<MapPose> poses;
  for (int i = 0; i < 40; ++i) {
    poses.push_back(at(coordinate(random), coordinate(random), angle(random)));
    world.add_body(kCar, poses.back(), i >= 35);  // the last five are static
  }
  for (int step = 0; step < 30; ++step) {
    for (std::size_t i = 0; i < 35; ++i) {
      poses[i] = at(poses[i].position.x + nudge(random), poses[i].position.y + nudge(random),
                    poses[i].heading + 0.2 * nudge(random));
      world.set_pose(static_cast<BodyId>(i), poses[i]);
    }
    std::vector<std::pair<BodyId, BodyId>> found;
    for (const Contact& contact : world.find_contacts())
      found.emplace_back(contact.first, contact.second);
    std::vector<std::pair<BodyId, BodyId>> expected;
    for (BodyId a = 0; a < 40; ++a)
      for (BodyId b = a + 1; b < 40; ++b)
        if (a < 35 && signed_distance(world.footprint(a), world.footprint(b)) < -1e-6)
          expected.emplace_back(a, b);
    // Pairs closer than the tolerance may go either way; every clear overlap must be found.
    for (const auto& pair : expected)
      EXPECT_NE(std::find(found.begin(), found.end(), pair), found.end())
          << "step " << step << ": " << pair.first << "-" << pair.second;
    for (const auto& [a, b] : found) {
      EXPECT_FALSE(a >= 35 && b >= 35) << "static-static";
      EXPECT_LT(signed_distance(world.footprint(a), world.footprint(b)), 1e-6);
    }
    EXPECT_TRUE(std::is_sorted(found.begin(), found.end()));
  }
}

TEST(CollisionWorld, DistanceIsFootprintDistanceForCars) {
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), false);
  world.add_body(kCar, at(10, 0), false);
  EXPECT_NEAR(world.distance(0, 1), 5.4, 1e-9);
  world.set_pose(1, at(10, 0, pi / 2));
  EXPECT_NEAR(world.distance(0, 1), 6.75, 1e-9) << "where libccd's GJK is wrong";
  world.set_pose(1, at(4.6, 0.5, pi));
  EXPECT_NEAR(world.distance(0, 1), 0.0, 1e-9) << "touching";
  world.set_pose(1, at(4.0, 0, pi));
  EXPECT_NEAR(world.distance(0, 1), -0.6, 1e-12) << "overlapping by 0.6";
  EXPECT_NEAR(world.distance(1, 0), -0.6, 1e-12);

  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> position(-7, 7), heading(-pi, pi);
  int negative = 0, positive = 0;
  for (int i = 0; i < 500; ++i) {
    world.set_pose(1, at(position(random), position(random), heading(random)));
    const double expected = signed_distance(world.footprint(0), world.footprint(1));
    EXPECT_NEAR(world.distance(0, 1), expected, 1e-6) << "pose " << i;
    (expected < 0 ? negative : positive) += 1;
  }
  EXPECT_GT(negative, 20);
  EXPECT_GT(positive, 20);
}

TEST(CollisionWorld, TallBallOverTheBonnetDoesNotTouch) {
  // A 6 m ball whose footprint reaches 0.2 m over the car's front, but 1.5 m above its roof.
  CollisionWorld world;
  world.add_body(kCar, at(0, 0), false);
  world.add_body({BodyShape::sphere, 6, 6, 6}, at(2.3 + 2.8, 0), true);
  EXPECT_LT(signed_distance(world.footprint(0), world.footprint(1)), 0);
  EXPECT_TRUE(world.find_contacts().empty());
  EXPECT_NEAR(world.distance(0, 1), std::hypot(2.8, 1.5) - 3, 1e-5);
}

TEST(CollisionWorld, TouchesStatic) {
  CollisionWorld world;
  EXPECT_FALSE(world.touches_static(kCar, at(0, 0))) << "an empty world";
  world.add_body({BodyShape::box, 2, 2, 1}, at(10, 0), true);
  world.add_body({BodyShape::cylinder, 1, 1, 1}, at(0, 10), true);
  world.add_body(kCar, at(-10, 0), false);
  EXPECT_TRUE(world.touches_static(kCar, at(7.0, 0)));
  EXPECT_FALSE(world.touches_static(kCar, at(6.6, 0))) << "0.1 m short";
  EXPECT_TRUE(world.touches_static(kCar, at(9.5, 2.5, pi / 2)));
  EXPECT_FALSE(world.touches_static(kCar, at(9.5, 3.5, pi / 2)));
  EXPECT_TRUE(world.touches_static(kPedestrian, at(0.5, 10.5)));
  EXPECT_FALSE(world.touches_static(kPedestrian, at(0.6, 10.6)));
  EXPECT_FALSE(world.touches_static(kCar, at(-10, 0))) << "moving bodies do not count";
}

TEST(CollisionWorld, BodiesAndFootprints) {
  CollisionWorld world;
  EXPECT_EQ(world.add_body(kCar, at(1, 2, 0.5), false), 0u);
  EXPECT_EQ(world.add_body(kPedestrian, at(3, 4), false), 1u);
  EXPECT_EQ(world.body_count(), 2u);
  const Footprint car = world.footprint(0);
  EXPECT_EQ(car.centre, (MapPoint{1, 2}));
  EXPECT_DOUBLE_EQ(car.heading, 0.5);
  EXPECT_DOUBLE_EQ(car.half_length, 2.3);
  EXPECT_DOUBLE_EQ(car.half_width, 0.95);
  EXPECT_FALSE(car.round);
  const Footprint walker = world.footprint(1);
  EXPECT_TRUE(walker.round);
  EXPECT_DOUBLE_EQ(walker.half_length, 0.3);

  CollisionWorld moved = std::move(world);
  moved.set_pose(1, at(3.3, 2));
  EXPECT_EQ(moved.find_contacts().size(), 1u);
}

TEST(CollisionWorld, RejectsBadBodies) {
  CollisionWorld world;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(world.add_body({BodyShape::box, 0, 1, 1}, at(0, 0), false), std::invalid_argument);
  EXPECT_THROW(world.add_body({BodyShape::box, 4, nan, 1}, at(0, 0), false), std::invalid_argument);
  EXPECT_THROW(world.add_body({BodyShape::cone, 1, 1, -1}, at(0, 0), true), std::invalid_argument);
  EXPECT_THROW(world.add_body({BodyShape::cylinder, 1, 2, 1}, at(0, 0), false),
               std::invalid_argument)
      << "a cylinder's length and width are its diameter";
  EXPECT_THROW(world.add_body(kCar, at(nan, 0), false), std::invalid_argument);
  EXPECT_EQ(world.body_count(), 0u);
}

}  // namespace
}  // namespace scenfuzz
