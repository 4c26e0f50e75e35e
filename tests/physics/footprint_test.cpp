// Footprint signed distances against hand-computed cases, against FCL's distance (its own GJK,
// GST_INDEP) on random separated pairs, and penetration depths against a brute-force search over
// directions; and the side of a body a contact point lies on.
#include "physics/collision/footprint.hpp"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <random>

namespace scenfuzz {
namespace {

constexpr double pi = std::numbers::pi;

// A 4.6 x 1.9 m car.
Footprint car(double x, double y, double heading) { return {{x, y}, heading, 2.3, 0.95, false}; }
Footprint rectangle(double x, double y, double heading, double length, double width) {
  return {{x, y}, heading, length / 2, width / 2, false};
}
Footprint disc(double x, double y, double radius) { return {{x, y}, 0.0, radius, radius, true}; }

TEST(FootprintDistance, ParallelBoxesApart) {
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(10, 0, 0)), 5.4, 1e-12) << "end to end";
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(0, 3, 0)), 1.1, 1e-12) << "side by side";
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(10, 1, 0)), 5.4, 1e-12) << "faces still face";
}

TEST(FootprintDistance, CornerToCornerIsEuclidean) {
  // The gap between the nearest corners is (3, 4).
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(4.6 + 3, 1.9 + 4, 0)), 5.0, 1e-12);
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(-4.6 - 3, -1.9 - 4, pi)), 5.0, 1e-12);
}

TEST(FootprintDistance, ExactRightAnglesWhereLibccdIsWrong) {
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(10, 0, pi / 2)), 10 - 2.3 - 0.95, 1e-12);
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(10, 0, pi)), 5.4, 1e-12);
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(0, 10, -pi / 2)), 10 - 0.95 - 2.3, 1e-12);
}

TEST(FootprintDistance, TouchingIsZero) {
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(4.6, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(4.6, 1.0, pi)), 0.0, 1e-12);
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(0, 1.9, 0)), 0.0, 1e-12);
  EXPECT_NEAR(signed_distance(car(0, 0, 0), disc(2.3 + 0.3, 0, 0.3)), 0.0, 1e-12);
  EXPECT_NEAR(signed_distance(disc(0, 0, 0.3), disc(0.8, 0, 0.5)), 0.0, 1e-12);
}

TEST(FootprintDistance, OverlapIsMinusThePenetrationDepth) {
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(4.0, 0, 0)), -0.6, 1e-12) << "rear-end by 0.6";
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(0, 1.5, 0)), -0.4, 1e-12) << "side by 0.4";
  EXPECT_NEAR(signed_distance(car(0, 0, 0), car(3.0, 0, pi / 2)), -0.25, 1e-12) << "T-bone";
  // A unit square's corner, turned 45 degrees, pushed into another's face.
  EXPECT_NEAR(signed_distance(rectangle(0, 0, 0, 1, 1), rectangle(1, 0, pi / 4, 1, 1)),
              1 - std::sqrt(2.0) / 2 - 0.5, 1e-12);
  // Wholly inside: the shortest way out is 1 m along x.
  EXPECT_NEAR(signed_distance(rectangle(0, 0, 0, 4, 2), rectangle(1.5, 0, 0, 1, 1)), -1.0, 1e-12);
  // Same place, same heading: out through the side, the car's width.
  EXPECT_NEAR(signed_distance(car(5, 5, 1), car(5, 5, 1)), -1.9, 1e-12);
}

TEST(FootprintDistance, DiscCases) {
  EXPECT_NEAR(signed_distance(disc(0, 0, 0.3), disc(2, 0, 0.5)), 1.2, 1e-12);
  EXPECT_NEAR(signed_distance(disc(0, 0, 0.3), disc(0, 0.6, 0.5)), -0.2, 1e-12);
  EXPECT_NEAR(signed_distance(car(0, 0, 0), disc(3.0, 0, 0.3)), 0.4, 1e-12) << "off the front";
  EXPECT_NEAR(signed_distance(car(0, 0, 0), disc(2.3 + 3, 0.95 + 4, 0.3)), 4.7, 1e-12)
      << "off a corner";
  EXPECT_NEAR(signed_distance(car(0, 0, 0), disc(2.0, 0, 0.3)), -0.6, 1e-12)
      << "centre inside, nearest the front";
  EXPECT_NEAR(signed_distance(car(0, 0, pi / 2), disc(0, 2.5, 0.3)), -0.1, 1e-12)
      << "turned car, disc at its front";
  Footprint turned_disc = disc(3.0, 0, 0.3);
  turned_disc.heading = 2.0;
  EXPECT_NEAR(signed_distance(car(0, 0, 0), turned_disc), 0.4, 1e-12) << "a disc has no heading";
}

TEST(FootprintDistance, IsSymmetric) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> position(-6, 6), heading(-pi, pi), size(0.3, 5);
  std::bernoulli_distribution round(0.3);
  for (int i = 0; i < 2000; ++i) {
    auto make = [&] {
      const double length = size(random);
      return round(random) ? disc(position(random), position(random), length / 2)
                           : rectangle(position(random), position(random), heading(random), length,
                                       size(random));
    };
    const Footprint a = make(), b = make();
    EXPECT_NEAR(signed_distance(a, b), signed_distance(b, a), 1e-12);
  }
}

fcl::Transform3d standing(const Footprint& body, double height) {
  fcl::Transform3d transform = fcl::Transform3d::Identity();
  transform.translation() = fcl::Vector3d(body.centre.x, body.centre.y, height / 2);
  transform.linear() = Eigen::AngleAxisd(body.heading, fcl::Vector3d::UnitZ()).toRotationMatrix();
  return transform;
}

double fcl_distance(const Footprint& a, const Footprint& b) {
  const double height = 1.5;
  auto shape = [height](const Footprint& body) -> std::shared_ptr<fcl::CollisionGeometryd> {
    if (body.round) return std::make_shared<fcl::Cylinderd>(body.half_length, height);
    return std::make_shared<fcl::Boxd>(2 * body.half_length, 2 * body.half_width, height);
  };
  const fcl::CollisionObjectd object_a(shape(a), standing(a, height));
  const fcl::CollisionObjectd object_b(shape(b), standing(b, height));
  fcl::DistanceRequestd request;
  request.gjk_solver_type = fcl::GST_INDEP;
  fcl::DistanceResultd result;
  fcl::distance(&object_a, &object_b, request, result);
  return result.min_distance;
}

TEST(FootprintDistance, AgreesWithFclOnSeparatedBoxes) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> position(-8, 8), heading(-pi, pi), size(0.5, 6);
  std::uniform_int_distribution<int> quarter_turns(0, 3);
  int compared = 0;
  for (int i = 0; i < 3000; ++i) {
    // Every third pair at an exact multiple of 90 degrees, where libccd's GJK goes wrong.
    const double turn_b = i % 3 == 0 ? quarter_turns(random) * pi / 2 : heading(random);
    const Footprint a =
        rectangle(position(random), position(random), 0.0, size(random), size(random));
    const Footprint b =
        rectangle(position(random), position(random), turn_b, size(random), size(random));
    const double footprint_distance = signed_distance(a, b);
    if (footprint_distance <= 1e-3) continue;
    ++compared;
    EXPECT_NEAR(footprint_distance, fcl_distance(a, b), 1e-6) << "pair " << i;
  }
  EXPECT_GT(compared, 1500);
}

TEST(FootprintDistance, AgreesWithFclOnSeparatedDiscsAndBoxes) {
  std::mt19937_64 random(13);
  std::uniform_real_distribution<double> position(-8, 8), heading(-pi, pi), size(0.3, 5);
  int compared = 0;
  for (int i = 0; i < 1000; ++i) {
    const Footprint a =
        rectangle(position(random), position(random), heading(random), size(random), size(random));
    const Footprint b = disc(position(random), position(random), size(random) / 2);
    const double footprint_distance = signed_distance(a, b);
    if (footprint_distance <= 1e-3) continue;
    ++compared;
    // On a curved cylinder GJK stops early, a little above the exact distance.
    const double fcl = fcl_distance(a, b);
    EXPECT_GE(fcl, footprint_distance - 1e-9) << "pair " << i;
    EXPECT_LE(fcl, footprint_distance + 1e-5 * std::max(1.0, footprint_distance)) << "pair " << i;
  }
  EXPECT_GT(compared, 500);
}

// The penetration depth of convex shapes is the least overlap of their projections over all
// directions; sampling directions finely gives an upper bound close to it.
double sampled_penetration_depth(const Footprint& a, const Footprint& b) {
  auto extent = [](const Footprint& body, double nx, double ny) {
    return body.half_length * std::abs(std::cos(body.heading) * nx + std::sin(body.heading) * ny) +
           body.half_width * std::abs(-std::sin(body.heading) * nx + std::cos(body.heading) * ny);
  };
  double least = std::numeric_limits<double>::infinity();
  constexpr int directions = 20000;
  for (int i = 0; i < directions; ++i) {
    const double angle = pi * i / directions, nx = std::cos(angle), ny = std::sin(angle);
    const double centres =
        std::abs((b.centre.x - a.centre.x) * nx + (b.centre.y - a.centre.y) * ny);
    least = std::min(least, extent(a, nx, ny) + extent(b, nx, ny) - centres);
  }
  return least;
}

TEST(FootprintDistance, PenetrationDepthMatchesBruteForce) {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> position(-2, 2), heading(-pi, pi), size(0.5, 5);
  int compared = 0;
  for (int i = 0; i < 300; ++i) {
    const Footprint a =
        rectangle(position(random), position(random), heading(random), size(random), size(random));
    const Footprint b =
        rectangle(position(random), position(random), heading(random), size(random), size(random));
    const double depth = -signed_distance(a, b);
    if (depth <= 0) continue;
    ++compared;
    const double sampled = sampled_penetration_depth(a, b);
    EXPECT_GE(sampled, depth - 1e-9) << "pair " << i;
    EXPECT_LE(sampled, depth + 1e-3) << "pair " << i;
  }
  EXPECT_GT(compared, 100);
}

TEST(FootprintSide, BoxSidesInItsOwnFrame) {
  const Footprint east = car(0, 0, 0);
  EXPECT_EQ(side_of(east, {2.3, 0}), BodySide::front);
  EXPECT_EQ(side_of(east, {2.2, 0.9}), BodySide::front) << "0.96 of the length, 0.95 of the width";
  EXPECT_EQ(side_of(east, {-2.3, 0.1}), BodySide::rear);
  EXPECT_EQ(side_of(east, {0, 0.95}), BodySide::left);
  EXPECT_EQ(side_of(east, {1.0, -0.95}), BodySide::right);
  EXPECT_EQ(side_of(east, {2.0, -0.9}), BodySide::right) << "0.87 of the length, 0.95 of the width";

  const Footprint north = car(10, 10, pi / 2);
  EXPECT_EQ(side_of(north, {10, 12.3}), BodySide::front);
  EXPECT_EQ(side_of(north, {10.2, 7.7}), BodySide::rear);
  EXPECT_EQ(side_of(north, {9.05, 10.5}), BodySide::left) << "west of a car facing north";
  EXPECT_EQ(side_of(north, {10.95, 9}), BodySide::right);
}

TEST(FootprintSide, DiscSidesByBearing) {
  Footprint walker = disc(0, 0, 0.3);
  walker.heading = pi / 2;  // walking north
  EXPECT_EQ(side_of(walker, {0.1, 0.3}), BodySide::front);
  EXPECT_EQ(side_of(walker, {-0.29, 0.3}), BodySide::front) << "just within 45 degrees";
  EXPECT_EQ(side_of(walker, {-0.3, 0.1}), BodySide::left);
  EXPECT_EQ(side_of(walker, {0.3, 0}), BodySide::right);
  EXPECT_EQ(side_of(walker, {0.1, -0.3}), BodySide::rear);
  walker.heading = pi;  // across the wrap-around of angles
  EXPECT_EQ(side_of(walker, {-0.3, -0.05}), BodySide::front);
  EXPECT_EQ(side_of(walker, {0, -0.3}), BodySide::left);
}

TEST(FootprintSide, Names) {
  EXPECT_EQ(body_side_name(BodySide::front), "front");
  EXPECT_EQ(body_side_name(BodySide::rear), "rear");
  EXPECT_EQ(body_side_name(BodySide::left), "left");
  EXPECT_EQ(body_side_name(BodySide::right), "right");
}

}  // namespace
}  // namespace scenfuzz
