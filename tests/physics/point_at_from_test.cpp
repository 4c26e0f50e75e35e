// point_at_from, walking from a known segment, must give Polyline::point_at's point bit for bit:
// from any hint, at any arc length (the vertices, both ends, beyond them).
#include "physics/map/point_at_from.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "tests/support/random_paths.hpp"

namespace scenfuzz {
namespace {

TEST(PointAtFrom, FromAnyHintIsPointAt) {
  std::mt19937_64 random(41);
  Polyline path = test::random_path(random, 200, 0.4);
  std::uniform_real_distribution<double> along(-5, path.length() + 5);
  std::uniform_int_distribution<std::size_t> hint(0, path.segment_count() + 3);
  std::vector<double> probes = {0, path.length(), -1, path.length() + 1};
  for (double s : path.arc_lengths()) probes.push_back(s);  // exactly at the vertices
  for (int i = 0; i < 2000; ++i) probes.push_back(along(random));
  for (double s : probes)
    for (int j = 0; j < 5; ++j) {
      const std::size_t from = hint(random);
      const MapPoint expected = path.point_at(s), found = point_at_from(path, s, from);
      EXPECT_EQ(found.x, expected.x) << "s " << s << " hint " << from;
      EXPECT_EQ(found.y, expected.y) << "s " << s << " hint " << from;
    }
}

}  // namespace
}  // namespace scenfuzz
