// pose_on_segment, a lane follower's pose at every step from blends it keeps, must be
// state_on_path's position and heading bit for bit: the traces' pinned hashes rest on it.
#include "physics/actors/path_pose.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "tests/support/random_paths.hpp"

namespace scenfuzz {
namespace {

TEST(PathPose, KeptBlendsGiveStateOnPathsPoseBitForBit) {
  std::mt19937_64 random(5);
  // Sharp turns too (up to 2 rad a vertex): blends that wrap through +-pi.
  for (double max_turn : {0.05, 0.5, 2.0}) {
    const Polyline path = test::random_path(random, 300, max_turn);
    const std::vector<double> headings = segment_headings(path);
    std::vector<VertexBlend> blends(path.points().size());
    for (std::size_t vertex = 1; vertex < path.segment_count(); ++vertex)
      blends[vertex] = vertex_blend(path, headings, vertex);
    std::uniform_real_distribution<double> along(0, path.length());
    int blended = 0;
    for (int i = 0; i < 20000; ++i) {
      // Vertices exactly, and the path's two ends, besides points anywhere.
      const double s = i % 7 == 0 ? path.arc_lengths()[static_cast<std::size_t>(i) % 300]
                       : i == 1   ? 0.0
                       : i == 2   ? path.length()
                                  : along(random);
      const KinematicState expected = state_on_path(path, headings, s, 3, 0);
      const MapPose got = pose_on_segment(path, headings, blends, path.segment_at(s), s);
      ASSERT_EQ(got.position.x, expected.x) << "s " << s;
      ASSERT_EQ(got.position.y, expected.y) << "s " << s;
      ASSERT_EQ(got.heading, expected.heading) << "s " << s;
      blended += expected.yaw_rate != 0;
    }
    EXPECT_GT(blended, 1000) << "max turn " << max_turn << ": the blends were hardly tested";
  }
}

}  // namespace
}  // namespace scenfuzz
