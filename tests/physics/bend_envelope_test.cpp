// BendEnvelope, with its slight bends skipped, headings computed lazily and values made only as far
// as they are read: below its speed bound it is bit for bit the envelope with every bend counted
// over the whole path, and on a gently curving path it computes no heading at all.
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

// Extends `envelope` to the path's end in random steps, checking every final vertex against the
// envelope of every bend below the bound after each.
void expect_full_below_bound(const Polyline& path, LazyHeadings& headings, BendEnvelope& envelope,
                             const std::vector<double>& full, std::mt19937_64& random) {
  std::uniform_int_distribution<std::size_t> step(1, 60);
  const double bound = envelope.speed_bound();
  for (std::size_t vertex = 0;; vertex += step(random)) {
    envelope.extend(path, headings, vertex);
    ASSERT_GT(envelope.final_count(), std::min(vertex, full.size() - 1));
    for (std::size_t i = 0; i < envelope.final_count(); ++i)
      ASSERT_EQ(std::min(envelope.at(i), bound), std::min(full[i], bound))
          << "vertex " << i << " after extending to " << vertex << ", bound " << bound;
    if (envelope.final_count() == full.size()) break;
  }
}

TEST(BendEnvelope, BelowTheSpeedBoundItIsTheEnvelopeOfEveryBendHoweverFarItIsMade) {
  std::mt19937_64 random(17);
  const double lateral = 3.0, deceleration = 2.5;
  for (double bound : {3.0, 12.0, 25.0, 50.0}) {
    for (int trial = 0; trial < 20; ++trial) {
      // The turn per metre of blend at which a bend caps the speed at exactly the bound.
      const double threshold = 2 * lateral / (bound * bound) / 2;
      Polyline path = wandering_path(random, threshold);
      LazyHeadings headings = lazy_headings(path);
      BendEnvelope envelope(path, lateral, deceleration, bound);
      expect_full_below_bound(path, headings, envelope, full_envelope(path, lateral, deceleration),
                              random);
    }
  }
}

TEST(BendEnvelope, ARaisedBoundGivesTheEnvelopeBelowTheNewBound) {
  std::mt19937_64 random(5);
  const double lateral = 3.0, deceleration = 2.5;
  Polyline path = wandering_path(random, 2 * lateral / (12.0 * 12.0) / 2);
  const std::vector<double> full = full_envelope(path, lateral, deceleration);
  LazyHeadings headings = lazy_headings(path);
  BendEnvelope envelope(path, lateral, deceleration, 5.0);
  envelope.extend(path, headings, 100);
  const std::size_t made = envelope.final_count();
  envelope.raise_bound(path, headings, 30.0);
  EXPECT_EQ(envelope.speed_bound(), 30.0);
  EXPECT_GE(envelope.final_count(), made);  // still as far as it was read
  for (std::size_t i = 0; i < envelope.final_count(); ++i)
    ASSERT_EQ(std::min(envelope.at(i), 30.0), std::min(full[i], 30.0)) << "vertex " << i;
  expect_full_below_bound(path, headings, envelope, full, random);
}

TEST(BendEnvelope, IsMadeOnlyAsFarAsItIsRead) {
  // 2 km straight, then a sharp corner: reading the start looks at none of the corner.
  std::vector<MapPoint> points;
  for (int i = 0; i <= 2000; ++i) points.push_back({static_cast<double>(i), 0});
  points.push_back({2000, 50});
  Polyline path(points);
  LazyHeadings headings = lazy_headings(path);
  BendEnvelope envelope(path, 3.0, 3.0, 12.0);  // reach: about 24 m
  envelope.extend(path, headings, 10);
  EXPECT_GT(envelope.reach(), 24.0);
  EXPECT_LT(envelope.reach(), 25.0);
  EXPECT_GT(envelope.final_count(), 10u);
  EXPECT_LT(envelope.final_count(), 40u);
  EXPECT_TRUE(std::isnan(headings.values[1999]));
  EXPECT_EQ(envelope.at(10), kInfinity);
  envelope.extend(path, headings, 2001);
  EXPECT_EQ(envelope.final_count(), path.points().size());
  EXPECT_FALSE(std::isnan(headings.values[1999]));
  // The corner caps the speed: about 24 m before it the envelope reaches the bound.
  EXPECT_LT(envelope.at(1995), 12.0);
  EXPECT_EQ(envelope.at(1900), kInfinity);
}

TEST(BendEnvelope, ComputesNoHeadingOnAGentleCurve) {
  // A 500 m arc of 2 km radius: every bend caps the speed far above 50 m/s.
  std::vector<MapPoint> points;
  for (int i = 0; i <= 500; ++i)
    points.push_back({2000 * std::cos(i / 2000.0), 2000 * std::sin(i / 2000.0)});
  Polyline path(points);
  LazyHeadings headings = lazy_headings(path);
  BendEnvelope envelope(path, 3.0, 2.5, 50.0);
  envelope.extend(path, headings, 500);
  EXPECT_TRUE(std::all_of(headings.values.begin(), headings.values.end(),
                          [](double h) { return std::isnan(h); }));
  EXPECT_EQ(envelope.at(0), kInfinity);
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
