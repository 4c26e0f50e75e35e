// The broadphase's sweep-and-prune: it yields exactly the pairs whose closed bounds overlap, as a
// test of every pair does, however the boxes move between calls, and never a static-static pair.
#include "physics/collision/body_sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace scenfuzz {
namespace {

std::vector<BodySweep::Pair> sorted(std::vector<BodySweep::Pair> pairs) {
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<BodySweep::Pair> every_overlap(const std::vector<SweepBox>& boxes,
                                           const std::vector<bool>& is_static) {
  std::vector<BodySweep::Pair> pairs;
  for (std::uint32_t a = 0; a < boxes.size(); ++a)
    for (std::uint32_t b = a + 1; b < boxes.size(); ++b)
      if (!(is_static[a] && is_static[b]) && boxes_overlap(boxes[a], boxes[b]))
        pairs.emplace_back(a, b);
  return pairs;
}

TEST(BodySweep, BoxesSharingAnEdgeOrACornerOverlap) {
  BodySweep sweep;
  sweep.add({0, 0, 1, 1}, false);
  sweep.add({1, 0, 2, 1}, false);  // shares an edge with 0
  sweep.add({2, 1, 3, 2}, false);  // shares a corner with 1
  sweep.add({3.5, 0, 4, 1}, false);
  std::vector<BodySweep::Pair> pairs;
  sweep.overlapping_pairs(pairs);
  EXPECT_EQ(sorted(pairs), (std::vector<BodySweep::Pair>{{0, 1}, {1, 2}}));
}

TEST(BodySweep, StaticBodiesPairOnlyWithMovingOnes) {
  BodySweep sweep;
  sweep.add({0, 0, 2, 2}, true);
  sweep.add({1, 1, 3, 3}, true);
  std::vector<BodySweep::Pair> pairs;
  sweep.overlapping_pairs(pairs);
  EXPECT_TRUE(pairs.empty());
  sweep.add({1.5, 1.5, 1.6, 1.6}, false);
  sweep.overlapping_pairs(pairs);
  EXPECT_EQ(sorted(pairs), (std::vector<BodySweep::Pair>{{0, 2}, {1, 2}}));
}

// Boxes jumping about (the sort order changes wholesale) and creeping (it changes a little), with
// many equal coordinates: the same pairs as brute force at every step.
TEST(BodySweep, MatchesBruteForceAsBoxesMove) {
  std::mt19937_64 random(11);
  std::uniform_int_distribution<int> grid(0, 30);  // integers: many exact ties and touches
  std::uniform_real_distribution<double> creep(-0.7, 0.7);
  std::uniform_int_distribution<int> size(0, 4);
  BodySweep sweep;
  std::vector<SweepBox> boxes;
  std::vector<bool> is_static;
  for (int i = 0; i < 60; ++i) {
    double x = grid(random), y = grid(random);
    boxes.push_back({x, y, x + size(random), y + size(random)});
    is_static.push_back(i % 7 == 0);
    sweep.add(boxes.back(), is_static.back());
  }
  std::vector<BodySweep::Pair> pairs;
  for (int step = 0; step < 200; ++step) {
    const bool jump = step % 10 == 0;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
      if (is_static[i]) continue;
      SweepBox& box = boxes[i];
      const double dx = jump ? grid(random) - box.min_x : creep(random);
      const double dy = jump ? grid(random) - box.min_y : creep(random);
      box = {box.min_x + dx, box.min_y + dy, box.max_x + dx, box.max_y + dy};
      sweep.move(i, box);
    }
    sweep.overlapping_pairs(pairs);
    for (const auto& [a, b] : pairs) EXPECT_LT(a, b);
    ASSERT_EQ(sorted(pairs), every_overlap(boxes, is_static)) << "step " << step;
  }
}

}  // namespace
}  // namespace scenfuzz
