// What an MPI worker sends rank 0 about a search (search_wire.hpp) reads back whole: the
// database rank 0 writes from it must be the one a single process writes, coverage included.
#include "fuzz/campaign/search_wire.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace scenfuzz {
namespace {

TEST(SearchWireTest, AResultReadsBackWithItsCoverageModesAndFiles) {
  CampaignSearchResult result;
  result.summary.evaluations = 5;
  result.summary.judged = 4;
  result.summary.failed = 1;
  result.evaluations = {{0, 1.5, false}, {1, std::nullopt, false}, {2, -0.25, true}};
  result.modes = {{"collision | car cutter | ego", "no_collision", "ego", "f/001.avu", 42}};
  result.best = -0.25;
  result.coverage = {"ego.following", "interaction.car.F.closing_0_2.far", "light.day"};
  const std::vector<WireFile> files = {{"f/001.svg", "<svg/>"}, {"f/001.avu", "text"}};

  std::vector<WireFile> read_files;
  const CampaignSearchResult read = decode_result(encode_result(result, files), read_files);
  EXPECT_EQ(read.coverage, result.coverage);
  EXPECT_EQ(read.summary.judged, 4u);
  ASSERT_EQ(read.evaluations.size(), 3u);
  EXPECT_EQ(read.evaluations[2].robustness, -0.25);
  EXPECT_FALSE(read.evaluations[1].robustness);
  ASSERT_EQ(read.modes.size(), 1u);
  EXPECT_EQ(read.modes[0].signature, "collision | car cutter | ego");
  EXPECT_EQ(read.best, -0.25);
  ASSERT_EQ(read_files.size(), 2u);
  EXPECT_EQ(read_files[1].content, "text");
}

}  // namespace
}  // namespace scenfuzz
