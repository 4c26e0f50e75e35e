// The actor grid lets a lane follower's scan skip actors far from its path, so it must never miss
// one whose position or predicted point lies in the rectangle asked about, and must leave out
// the actors that are not on the map.
#include "physics/simulation/actor_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "physics/simulation/predicted_points.hpp"

namespace scenfuzz {
namespace {

bool inside(MapPoint p, MapPoint low, MapPoint high) {
  return p.x >= low.x && p.x <= high.x && p.y >= low.y && p.y <= high.y;
}

TEST(ActorGrid, FindsEveryActorWithAPointInTheRectangle) {
  for (double spread : {30.0, 400.0, 5000.0}) {  // one cell, a few, many
    std::mt19937_64 random(static_cast<std::uint64_t>(spread));
    std::uniform_real_distribution<double> coordinate(-spread, spread), heading(-3.2, 3.2),
        speed(0, 20), size(0.5, 12);
    const std::size_t count = 150;
    std::vector<KinematicState> states(count);
    std::vector<double> lengths(count), widths(count);
    std::vector<std::uint8_t> present(count);
    for (std::size_t k = 0; k < count; ++k) {
      states[k].x = 552000 + coordinate(random);
      states[k].y = 4182000 + coordinate(random);
      states[k].heading = heading(random);
      states[k].speed = k % 5 == 0 ? 0 : speed(random);
      lengths[k] = size(random);
      widths[k] = size(random) / 3;
      present[k] = k % 7 == 3 ? 0 : 1;
    }
    std::vector<MapPoint> predicted;
    predict_points(states, 1.5, predicted);
    ActorGrid grid;
    grid.build(states, predicted, lengths, widths, present);
    double largest = 0;
    for (std::size_t k = 0; k < count; ++k)
      if (present[k]) largest = std::max(largest, lengths[k] / 2 + widths[k] / 2);
    EXPECT_EQ(grid.largest_half_extent(), largest);

    std::uniform_real_distribution<double> half(1, spread / 2);
    std::vector<std::uint32_t> near;
    for (int query = 0; query < 300; ++query) {
      MapPoint centre{552000 + coordinate(random) * 1.2, 4182000 + coordinate(random) * 1.2};
      double hx = half(random), hy = half(random);
      MapPoint low{centre.x - hx, centre.y - hy}, high{centre.x + hx, centre.y + hy};
      grid.near(low, high, near);
      EXPECT_TRUE(std::is_sorted(near.begin(), near.end()));
      EXPECT_TRUE(std::adjacent_find(near.begin(), near.end()) == near.end());
      for (std::uint32_t k : near) EXPECT_TRUE(present[k]) << "absent actor " << k;
      for (std::size_t k = 0; k < count; ++k) {
        bool wanted = present[k] && (inside({states[k].x, states[k].y}, low, high) ||
                                     inside(predicted[k], low, high));
        if (wanted) {
          EXPECT_TRUE(std::binary_search(near.begin(), near.end(), static_cast<std::uint32_t>(k)))
              << "spread " << spread << " query " << query << " missed actor " << k;
        }
      }
    }
  }
}

TEST(ActorGrid, EveryActorIsFiledWhenNoneIsMarkedAbsent) {
  std::vector<KinematicState> states(3);
  states[1].x = 100;
  states[2].y = -100;
  std::vector<MapPoint> predicted;
  predict_points(states, 1.5, predicted);
  std::vector<double> lengths{4, 4, 0.5}, widths{2, 2, 0.5};
  ActorGrid grid;
  grid.build(states, predicted, lengths, widths, {});
  std::vector<std::uint32_t> near;
  grid.near({-1000, -1000}, {1000, 1000}, near);
  EXPECT_EQ(near, (std::vector<std::uint32_t>{0, 1, 2}));
  grid.near({90, -10}, {110, 10}, near);  // may hold neighbours, must hold actor 1
  EXPECT_TRUE(std::find(near.begin(), near.end(), 1u) != near.end());
}

TEST(PredictedPoints, MovingActorsAheadAlongTheirHeadingStandingOnesWhereTheyAre) {
  std::vector<KinematicState> states(3);
  states[0].speed = 10;  // heading 0: 15 m east in 1.5 s
  states[1].x = 5;
  states[1].speed = 0.05;  // standing
  states[2].speed = 2;
  states[2].reversing = true;  // backwards
  std::vector<MapPoint> points;
  predict_points(states, 1.5, points);
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0].x, 15);
  EXPECT_EQ(points[1].x, 5);
  EXPECT_EQ(points[2].x, -3);
  EXPECT_EQ(points[0].x, predicted_point(states[0], 1.5).x);
}

}  // namespace
}  // namespace scenfuzz
