// Characterization of the third-party libraries scenfuzz relies on (Drake style): each test pins
// one behaviour we build on, at known inputs against known answers, so that a package upgrade
// that changes it fails here first. It also proves that the whole dependency set links.
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>
#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <nlopt.hpp>
#include <numbers>
#include <vector>

namespace {

// A car's footprint box, as in shared/reference/dependencies.md: 4.6 x 1.9 x 1.5 m.
constexpr double kLength = 4.6, kWidth = 1.9, kHeight = 1.5;

fcl::Transform3d pose(double x, double y, double yaw) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  t.translation() = fcl::Vector3d(x, y, 0.0);
  t.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return t;
}

bool boxes_collide(const fcl::Transform3d& a_pose, const fcl::Transform3d& b_pose) {
  auto box = std::make_shared<fcl::Boxd>(kLength, kWidth, kHeight);
  fcl::CollisionObjectd a(box, a_pose), b(box, b_pose);
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(&a, &b, request, result);
  return result.isCollision();
}

double boxes_distance(const fcl::Transform3d& a_pose, const fcl::Transform3d& b_pose,
                      fcl::GJKSolverType solver = fcl::GST_LIBCCD) {
  auto box = std::make_shared<fcl::Boxd>(kLength, kWidth, kHeight);
  fcl::CollisionObjectd a(box, a_pose), b(box, b_pose);
  fcl::DistanceRequestd request;
  request.gjk_solver_type = solver;
  fcl::DistanceResultd result;
  fcl::distance(&a, &b, request, result);
  return result.min_distance;
}

TEST(FclCharacterization, BoxBoxCollideAtKnownPoses) {
  EXPECT_TRUE(boxes_collide(pose(0, 0, 0), pose(4.0, 0, 0))) << "overlap 0.6 m end to end";
  EXPECT_TRUE(boxes_collide(pose(0, 0, 0), pose(0, 1.5, 0))) << "side by side, overlap 0.4 m";
  EXPECT_TRUE(boxes_collide(pose(0, 0, 0), pose(3.0, 0, std::numbers::pi / 2)))
      << "T-bone: 2.3 + 0.95 > 3.0";
  EXPECT_FALSE(boxes_collide(pose(0, 0, 0), pose(10.0, 0, 0)));
  EXPECT_FALSE(boxes_collide(pose(0, 0, 0), pose(0, 2.0, 0))) << "adjacent lanes, 0.1 m gap";
  EXPECT_FALSE(boxes_collide(pose(0, 0, 0), pose(3.5, 0, std::numbers::pi / 2)));
}

TEST(FclCharacterization, BoxBoxDistanceWhenApart) {
  // End to end along x: 10 - 4.6 = 5.4 m.
  EXPECT_NEAR(boxes_distance(pose(0, 0, 0), pose(10.0, 0, 0)), 5.4, 1e-6);
  // Side by side: 3 - 1.9 = 1.1 m.
  EXPECT_NEAR(boxes_distance(pose(0, 0, 0), pose(0, 3.0, 0)), 1.1, 1e-6);
  // Turned 0.3 rad, its nearest corner (7.522, 0.227) faces the first box's front: 5.222 m.
  const double c = std::cos(0.3), s = std::sin(0.3);
  const double nearest_x = 10.0 - (kLength / 2 * c + kWidth / 2 * s);
  EXPECT_NEAR(boxes_distance(pose(0, 0, 0), pose(10.0, 0, 0.3)), nearest_x - kLength / 2, 1e-6);
}

// KNOWN BUG, pinned: with the default GJK solver (libccd), box-box distance is wrong when the
// boxes' axes are exactly at a right angle or exactly opposed (an NPC turned exactly 90 degrees,
// or oncoming traffic in a straight lane), degenerate cases for libccd's GJK. Slightly off those
// angles, and in 10,000 random poses, both solvers agree to 1 mm. GST_INDEP (FCL's own GJK) is
// exact: use it for distances. If this test starts failing, FCL or libccd fixed the bug.
TEST(FclCharacterization, DefaultSolverDistanceIsWrongAtExactRightAngles) {
  const double pi = std::numbers::pi;
  // Turned 90 degrees: the 1.9 m side faces us, 10 - 2.3 - 0.95 = 6.75 m.
  EXPECT_NEAR(boxes_distance(pose(0, 0, 0), pose(10, 0, pi / 2), fcl::GST_INDEP), 6.75, 1e-9);
  EXPECT_NEAR(boxes_distance(pose(0, 0, 0), pose(10, 0, pi / 2), fcl::GST_LIBCCD), 7.4917, 1e-3);
  // Turned 180 degrees: nose to nose, 5.4 m.
  EXPECT_NEAR(boxes_distance(pose(0, 0, 0), pose(10, 0, pi), fcl::GST_INDEP), 5.4, 1e-9);
  EXPECT_NEAR(boxes_distance(pose(0, 0, 0), pose(10, 0, pi), fcl::GST_LIBCCD), 5.7245, 1e-3);
  // 0.01 rad off the right angle, libccd is right again.
  EXPECT_NEAR(boxes_distance(pose(0, 0, 0), pose(10, 0, 1.58), fcl::GST_LIBCCD),
              boxes_distance(pose(0, 0, 0), pose(10, 0, 1.58), fcl::GST_INDEP), 1e-6);
}

double dubins_distance(double x0, double y0, double yaw0, double x1, double y1, double yaw1) {
  auto space = std::make_shared<ompl::base::DubinsStateSpace>(5.0);  // turning radius 5 m
  ompl::base::ScopedState<ompl::base::SE2StateSpace> from(space), to(space);
  from->setXY(x0, y0);
  from->setYaw(yaw0);
  to->setXY(x1, y1);
  to->setYaw(yaw1);
  return space->distance(from.get(), to.get());
}

TEST(OmplCharacterization, DubinsDistanceWithTurningRadius5) {
  constexpr double r = 5.0, pi = std::numbers::pi;
  // Straight ahead.
  EXPECT_NEAR(dubins_distance(0, 0, 0, 20, 0, 0), 20.0, 1e-9);
  // A U-turn to the left: half a circle of radius 5 around (0, 5), pi * r.
  EXPECT_NEAR(dubins_distance(0, 0, 0, 0, 2 * r, pi), pi * r, 1e-9);
  // A quarter circle to (5, 5) facing north, then 10 m straight on: pi/2 * r + 10.
  EXPECT_NEAR(dubins_distance(0, 0, 0, r, 15, pi / 2), pi / 2 * r + 10.0, 1e-9);
}

TEST(NloptCharacterization, CobylaFindsTheMinimumOfAQuadratic) {
  // f(x, y) = (x - 1)^2 + 2 (y + 2)^2 + 3, minimum 3 at (1, -2).
  auto objective = [](const std::vector<double>& x, std::vector<double>&, void*) {
    return (x[0] - 1.0) * (x[0] - 1.0) + 2.0 * (x[1] + 2.0) * (x[1] + 2.0) + 3.0;
  };
  nlopt::opt opt(nlopt::LN_COBYLA, 2);
  opt.set_lower_bounds({-5.0, -5.0});
  opt.set_upper_bounds({5.0, 5.0});
  opt.set_min_objective(+objective, nullptr);
  opt.set_xtol_abs(1e-9);
  opt.set_maxeval(2000);
  std::vector<double> x = {4.0, 4.0};
  double minimum = 0.0;
  const nlopt::result result = opt.optimize(x, minimum);
  EXPECT_GT(result, 0) << "a success code";
  EXPECT_NEAR(x[0], 1.0, 1e-4);
  EXPECT_NEAR(x[1], -2.0, 1e-4);
  EXPECT_NEAR(minimum, 3.0, 1e-8);
}

TEST(TbbCharacterization, ParallelReduceSums) {
  constexpr std::int64_t n = 1'000'000;
  const std::int64_t sum = tbb::parallel_reduce(
      tbb::blocked_range<std::int64_t>(1, n + 1), std::int64_t{0},
      [](const tbb::blocked_range<std::int64_t>& range, std::int64_t partial) {
        for (std::int64_t i = range.begin(); i != range.end(); ++i) partial += i;
        return partial;
      },
      std::plus<>());
  EXPECT_EQ(sum, n * (n + 1) / 2);
}

}  // namespace
