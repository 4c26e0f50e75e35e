// Edit distances for "did you mean" suggestions: the bounded form agrees with the full one.
#include "lang/edit_distance.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace scenfuzz {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("npc1", "npc_1"), 1u);
}

TEST(EditDistance, TheBoundedFormIsExactUpToItsLimitAndLimitPlusOneBeyond) {
  const std::vector<std::string> words = {"",         "a",          "ego",         "egos",
                                          "npc1",     "npc_1",      "kitten",      "sitting",
                                          "value_12", "valeu_1225", "ego_vehicle", "vehicle_ego"};
  for (const std::string& a : words)
    for (const std::string& b : words)
      for (std::size_t limit = 0; limit <= 12; ++limit) {
        const std::size_t full = edit_distance(a, b);
        EXPECT_EQ(edit_distance_within(a, b, limit), full <= limit ? full : limit + 1)
            << a << " / " << b << " within " << limit;
      }
}

}  // namespace
}  // namespace scenfuzz
