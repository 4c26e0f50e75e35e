// bend_envelope with its slight bends skipped and headings computed lazily: below the body's
// top speed it is bit for bit the envelope with every bend counted, and on a gently curving path
// it computes no heading at all (the follower setup's atan2 per segment it replaced).
#include "physics/simulation/bend_envelope.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "physics/actors/path_pose.hpp"

namespace scenfuzz {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The envelope as the follower computed it before: every vertex's bend counted.
std::vector<double> full_envelope(const Polyline& path, double lateral, double deceleration) {
  const std::vector<double> headings = segment_headings(path);
  const std::size_t count = path.points().size();
  std::vector<double> envelope(count, kInfinity);
  for (std::size_t i = count; i-- > 0;) {
    double curvature = vertex_curvature(path, headings, i);
    double cap = curvature > 1e-9 ? std::sqrt(lateral / curvature) : kInfinity;
    if (i + 1 < count) {
      double ds = path.arc_lengths()[i + 1] - path.arc_lengths()[i];
      cap = std::min(cap, std::sqrt(envelope[i + 1] * envelope[i + 1] + 2 * deceleration * ds));
    }
    envelope[i] = cap;
  }
  return envelope;
}

// A lane-like path: segments of 0.3-3 m, turning by amounts from nothing to sharp corners,
// including turns right at the skip test's threshold for the given top speed.
Polyline wandering_path(std::mt19937_64& random, double threshold_turn) {
  std::uniform_real_distribution<double> length(0.3, 3.0);
  std::uniform_int_distribution<int> kind(0, 4);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<MapPoint> points{{1000, -2000}};
  double heading = 0.3;
  for (int i = 0; i < 400; ++i) {
    const double ds = length(random);
    switch (kind(random)) {
      case 0: break;                                                              // straight on
      case 1: heading += 1e-6 * unit(random); break;                              // rounding-level
      case 2: heading += threshold_turn * ds * (1 + 0.05 * unit(random)); break;  // near threshold
      case 3: heading += 0.02 * unit(random); break;                              // a gentle bend
      default: heading += 0.6 * unit(random); break;                              // a corner
    }
    points.push_back(
        {points.back().x + ds * std::cos(heading), points.back().y + ds * std::sin(heading)});
  }
  return Polyline(points);
}

TEST(BendEnvelope, BelowTopSpeedItIsTheEnvelopeOfEveryBend) {
  std::mt19937_64 random(17);
  const double lateral = 3.0, deceleration = 2.5;
  for (double max_speed : {3.0, 12.0, 25.0, 50.0}) {
    for (int trial = 0; trial < 20; ++trial) {
      // The turn per metre of blend at which a bend caps the speed at exactly max_speed.
      const double threshold = 2 * lateral / (max_speed * max_speed) / 2;
      Polyline path = wandering_path(random, threshold);
      LazyHeadings headings = lazy_headings(path);
      const std::vector<double> lazy =
          bend_envelope(path, headings, lateral, deceleration, max_speed);
      const std::vector<double> full = full_envelope(path, lateral, deceleration);
      ASSERT_EQ(lazy.size(), full.size());
      for (std::size_t i = 0; i < full.size(); ++i)
        ASSERT_EQ(std::min(lazy[i], max_speed), std::min(full[i], max_speed))
            << "vertex " << i << ", max speed " << max_speed;
    }
  }
}

TEST(BendEnvelope, ComputesNoHeadingOnAGentleCurve) {
  // A 500 m arc of 2 km radius: every bend caps the speed far above 50 m/s.
  std::vector<MapPoint> points;
  for (int i = 0; i <= 500; ++i)
    points.push_back({2000 * std::cos(i / 2000.0), 2000 * std::sin(i / 2000.0)});
  Polyline path(points);
  LazyHeadings headings = lazy_headings(path);
  const std::vector<double> envelope = bend_envelope(path, headings, 3.0, 2.5, 50.0);
  EXPECT_TRUE(std::all_of(headings.values.begin(), headings.values.end(),
                          [](double h) { return std::isnan(h); }));
  EXPECT_GT(envelope.front(), 50.0);
}

TEST(BendEnvelope, LazyHeadingsAreTheSegmentHeadings) {
  std::mt19937_64 random(3);
  Polyline path = wandering_path(random, 0.01);
  const std::vector<double> expected = segment_headings(path);
  LazyHeadings headings = lazy_headings(path);
  ensure_headings(headings, path, 5, 9);
  EXPECT_TRUE(std::isnan(headings.values[4]));
  EXPECT_EQ(headings.values[7], expected[7]);
  EXPECT_TRUE(std::isnan(headings.values[10]));
  for (std::size_t k = expected.size(); k-- > 0;)
    EXPECT_EQ(heading_of(headings, path, k), expected[k]);
  ensure_headings(headings, path, expected.size() - 2, expected.size() + 5);  // clamped at the end
}

}  // namespace
}  // namespace scenfuzz
