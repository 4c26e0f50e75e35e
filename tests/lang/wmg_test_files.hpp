// Shared by the WMG SDL level-2 tests: the corpus folder, a small valid file assembled from
// replaceable parts, and a check that a location spans exactly a given piece of text.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "lang/source_location.hpp"

namespace scenfuzz::wmg::test {

inline std::filesystem::path wmg_corpus_dir() {
  return std::filesystem::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "wmg";
}

// The smallest valid file, in parts that a test replaces one at a time.
struct Parts {
  std::string header = "VERSION: 1.0\nAUTHOR: 'a'\n";
  std::string scenery = "SCENERY ELEMENTS:\nDO: 'd' [S] as:\nJunctions: None\nRoads: None\n";
  std::string dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\nWHEN: [Ego] is [Going Ahead]\n"
      "DO: AUTO\nEND\n";
  std::string internal;
  std::string environment =
      "ENVIRONMENT ELEMENTS:\nDO: [E]\nCloudiness [0]\nRainfall [Light Rain: 0]\n"
      "Time of the day [Any]\nIllumination [Day] with [Sun] as light source\n";
  std::string traffic;

  std::string text() const {
    return header + scenery + dynamics + internal + environment + traffic;
  }
};

// A road element with every mandatory part; `middle` goes after the roadside feature and
// `tail` replaces the length and lane width.
inline std::string road(const std::string& middle = "",
                        const std::string& tail = "Length [100] AND Lane width [3.5]\n") {
  return "R1: START\n"
         "Road type [Motorway] as [R1] with zone as [N/A] AND speed limit of [100]\n"
         "in a [Rural] environment with Number of lanes [1] as [R1.L1]\n"
         "Road traffic direction [Left-handed] Lane type [Traffic lane] Lane markings [Solid "
         "line]\n"
         "Horizontal road geometry [Straight] Vertical road geometry [Level plane]\n"
         "Transverse road geometry [Divided] Road banking angle [Level Plane]\n"
         "with [No] roadside feature\n" +
         middle + tail + "END\n";
}

// A road with `lanes` traffic lanes, the given geometry lines, length and lane width.
inline std::string road_text(const std::string& id, int lanes, const std::string& geometry,
                             const std::string& tail, const std::string& start = "START",
                             const std::string& end = "END", const std::string& speed = "100") {
  std::string lane_list;
  for (int k = 1; k <= lanes; ++k) lane_list += (k > 1 ? ", " : "") + id + ".L" + std::to_string(k);
  return id + ": " + start + "\nRoad type [Motorway] as [" + id +
         "] with zone as [N/A] AND speed limit of [" + speed +
         "]\nin a [Rural] environment with Number of lanes [" + std::to_string(lanes) + "] as [" +
         lane_list +
         "]\nRoad traffic direction [Left-handed] Lane type [Traffic lane] Lane markings [Solid "
         "line]\n" +
         geometry +
         " Vertical road geometry [Level plane]\nTransverse road geometry [Divided] Road banking "
         "angle [Level Plane]\nwith [No] roadside feature\n" +
         tail + "\n" + end + "\n";
}

inline std::string scenery_with_roads(const std::string& roads,
                                      const std::string& junctions = "None\n") {
  return "SCENERY ELEMENTS:\nDO: 'd' [S] as:\nJunctions: " + junctions + "Roads:\n" + roads;
}

// Expects `location` to cover exactly the first occurrence of `piece` at or after `from` in
// `text` (offset, length, 1-based line and column).
inline void expect_spans(const SourceLocation& location, const std::string& text,
                         const std::string& piece, std::size_t from = 0) {
  std::size_t offset = text.find(piece, from);
  ASSERT_NE(offset, std::string::npos) << "'" << piece << "' is not in the text";
  std::uint32_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  EXPECT_EQ(location.offset, offset) << piece;
  EXPECT_EQ(location.length, piece.size()) << piece;
  EXPECT_EQ(location.line, line) << piece;
  EXPECT_EQ(location.column, column) << piece;
}

}  // namespace scenfuzz::wmg::test
