// Apollo HD map reader: every sample map in shared/maps/apollo read in text and binary form (the
// counts of its README, and the two forms giving the same description), facts pinned from
// san_francisco's base_map.txt, a small hand-written map for what the samples lack (yield signs,
// multi-segment curves, unknown fields), and malformed input, which must raise MapError naming the
// file and never crash.
#include "physics/map/apollo_map_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "physics/map/road_map.hpp"
#include "tests/support/shared_dir.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

struct SampleMap {
  const char* name;
  std::size_t lanes;
  std::size_t junctions;
  std::size_t signals;
  std::size_t stop_signs;
  std::size_t crosswalks;
};

// shared/maps/apollo/README.md
constexpr SampleMap kSampleMaps[] = {
    {"san_francisco", 1524, 91, 201, 9, 43},
    {"gomentum", 289, 33, 16, 24, 30},
    {"shalun", 235, 17, 28, 23, 28},
    {"borregas_ave", 60, 2, 15, 2, 6},
    {"cubetown", 18, 2, 3, 3, 0},
    {"straight_1_lane_pedestrian_crosswalk", 3, 0, 0, 0, 1},
    {"single_lane_road", 2, 0, 0, 0, 0},
    {"wide_flat_map", 1, 0, 0, 0, 0},
};

const char kUtmZone10[] = "+proj=utm +zone=10 +ellps=WGS84 +datum=WGS84 +units=m +no_defs";

fs::path apollo_dir() { return test::shared_dir() / "maps" / "apollo"; }

std::size_t sign_count(const MapDescription& map, SignKind kind) {
  std::size_t count = 0;
  for (const SignDescription& sign : map.signs) count += sign.kind == kind ? 1 : 0;
  return count;
}

// ---- comparing two descriptions: the first difference, as text, or "" ----

std::string to_string(const std::vector<MapPoint>& points) {
  std::ostringstream out;
  out.precision(17);
  out << points.size() << " points";
  if (!points.empty()) out << " from (" << points.front().x << ", " << points.front().y << ")";
  return out.str();
}

std::string to_string(const std::vector<std::string>& ids) {
  std::string out = "{";
  for (const std::string& id : ids) out += " " + id;
  return out + " }";
}

template <class T>
std::string difference(const std::string& what, const T& a, const T& b) {
  if (a == b) return "";
  return what + ": " + to_string(a) + " vs " + to_string(b);
}

std::string difference(const std::string& what, const std::vector<LaneCrossingDescription>& a,
                       const std::vector<LaneCrossingDescription>& b) {
  if (a.size() != b.size())
    return what + ": " + std::to_string(a.size()) + " vs " + std::to_string(b.size()) + " lanes";
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].lane != b[i].lane || a[i].s_begin != b[i].s_begin || a[i].s_end != b[i].s_end)
      return what + ": crossing " + std::to_string(i) + " differs (" + a[i].lane + " vs " +
             b[i].lane + ")";
  return "";
}

std::string difference(const std::string& what, const std::vector<std::vector<MapPoint>>& a,
                       const std::vector<std::vector<MapPoint>>& b) {
  if (a.size() != b.size())
    return what + ": " + std::to_string(a.size()) + " vs " + std::to_string(b.size()) + " lines";
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::string d = difference(what + "[" + std::to_string(i) + "]", a[i], b[i]); !d.empty())
      return d;
  return "";
}

std::string first_of(std::initializer_list<std::string> differences) {
  for (const std::string& d : differences)
    if (!d.empty()) return d;
  return "";
}

std::string lane_difference(const LaneDescription& a, const LaneDescription& b) {
  const std::string at = "lane " + a.id + " ";
  return first_of({
      a.id == b.id ? "" : "lane ids " + a.id + " vs " + b.id,
      difference(at + "centre_line", a.centre_line, b.centre_line),
      difference(at + "left_boundary", a.left_boundary, b.left_boundary),
      difference(at + "right_boundary", a.right_boundary, b.right_boundary),
      a.left_width == b.left_width ? "" : at + "left_width",
      a.right_width == b.right_width ? "" : at + "right_width",
      a.left_boundary_type == b.left_boundary_type ? "" : at + "left_boundary_type",
      a.right_boundary_type == b.right_boundary_type ? "" : at + "right_boundary_type",
      a.speed_limit == b.speed_limit ? "" : at + "speed_limit",
      a.turn == b.turn ? "" : at + "turn",
      difference(at + "successors", a.successors, b.successors),
      difference(at + "predecessors", a.predecessors, b.predecessors),
      difference(at + "left_forward_neighbours", a.left_forward_neighbours,
                 b.left_forward_neighbours),
      difference(at + "right_forward_neighbours", a.right_forward_neighbours,
                 b.right_forward_neighbours),
      difference(at + "left_reverse_neighbours", a.left_reverse_neighbours,
                 b.left_reverse_neighbours),
      difference(at + "right_reverse_neighbours", a.right_reverse_neighbours,
                 b.right_reverse_neighbours),
      a.junction == b.junction ? "" : at + "junction " + a.junction + " vs " + b.junction,
  });
}

// Text and binary forms of one map must describe it identically, to the bit: protobuf's text
// format prints doubles so that they read back exactly.
std::string map_difference(const MapDescription& a, const MapDescription& b) {
  if (a.name != b.name) return "name " + a.name + " vs " + b.name;
  if (a.projection != b.projection) return "projection";
  if (a.lanes.size() != b.lanes.size()) return "lane count";
  for (std::size_t i = 0; i < a.lanes.size(); ++i)
    if (std::string d = lane_difference(a.lanes[i], b.lanes[i]); !d.empty()) return d;
  if (a.junctions.size() != b.junctions.size()) return "junction count";
  for (std::size_t i = 0; i < a.junctions.size(); ++i) {
    const std::string at = "junction " + a.junctions[i].id + " ";
    if (std::string d = first_of({
            a.junctions[i].id == b.junctions[i].id ? "" : at + "id",
            difference(at + "outline", a.junctions[i].outline, b.junctions[i].outline),
        });
        !d.empty())
      return d;
  }
  if (a.traffic_lights.size() != b.traffic_lights.size()) return "traffic light count";
  for (std::size_t i = 0; i < a.traffic_lights.size(); ++i) {
    const TrafficLightDescription& x = a.traffic_lights[i];
    const TrafficLightDescription& y = b.traffic_lights[i];
    const std::string at = "signal " + x.id + " ";
    if (std::string d = first_of({
            x.id == y.id ? "" : at + "id",
            difference(at + "heads", x.heads, y.heads),
            difference(at + "stop_lines", x.stop_lines, y.stop_lines),
            difference(at + "lanes", x.lanes, y.lanes),
            x.plan.has_value() == y.plan.has_value() ? "" : at + "plan",
        });
        !d.empty())
      return d;
  }
  if (a.signs.size() != b.signs.size()) return "sign count";
  for (std::size_t i = 0; i < a.signs.size(); ++i) {
    const SignDescription& x = a.signs[i];
    const SignDescription& y = b.signs[i];
    const std::string at = "sign " + x.id + " ";
    if (std::string d = first_of({
            x.id == y.id ? "" : at + "id",
            x.kind == y.kind ? "" : at + "kind",
            difference(at + "stop_lines", x.stop_lines, y.stop_lines),
            difference(at + "lanes", x.lanes, y.lanes),
        });
        !d.empty())
      return d;
  }
  if (a.crosswalks.size() != b.crosswalks.size()) return "crosswalk count";
  for (std::size_t i = 0; i < a.crosswalks.size(); ++i) {
    const CrosswalkDescription& x = a.crosswalks[i];
    const CrosswalkDescription& y = b.crosswalks[i];
    const std::string at = "crosswalk " + std::to_string(i) + " (" + x.id + ") ";
    if (std::string d = first_of({
            x.id == y.id ? "" : at + "id",
            difference(at + "outline", x.outline, y.outline),
            difference(at + "lanes", x.lanes, y.lanes),
        });
        !d.empty())
      return d;
  }
  return "";
}

// ---- scratch files for malformed input ----

class ScratchDir {
 public:
  ScratchDir() {
    std::random_device random;
    path_ = fs::temp_directory_path() /
            ("scenfuzz_apollo_test_" + std::to_string(random()) + "_" +
             std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const fs::path& path() const { return path_; }

  fs::path write(const std::string& name, const std::string& bytes) const {
    const fs::path file = path_ / name;
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return file;
  }

 private:
  fs::path path_;
};

std::string read_all(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// The reader must throw MapError naming the file; returns its message ("" if it did not throw).
template <class Read>
std::string map_error(Read read, const fs::path& file) {
  try {
    read(file);
  } catch (const MapError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos)
        << "the message does not name " << file << ": " << error.what();
    return error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << file << ": not a MapError: " << error.what();
    return error.what();
  }
  ADD_FAILURE() << file << ": read without error";
  return "";
}

// Offsets just past each top-level field of a binary protobuf message. Binary protobuf has no
// framing, so a copy cut at one of them is a valid (smaller) message; cut anywhere else, it is
// truncated inside a field.
std::set<std::size_t> top_level_field_ends(const std::string& bytes) {
  std::set<std::size_t> ends;
  std::size_t at = 0;
  const auto varint = [&] {
    std::uint64_t value = 0;
    for (int shift = 0; at < bytes.size() && shift < 64; shift += 7) {
      const auto byte = static_cast<unsigned char>(bytes[at++]);
      value |= std::uint64_t{byte & 0x7Fu} << shift;
      if ((byte & 0x80u) == 0) break;
    }
    return value;
  };
  while (at < bytes.size()) {
    switch (varint() & 7) {
      case 0: varint(); break;
      case 1: at += 8; break;
      case 2: at += static_cast<std::size_t>(varint()); break;
      case 5: at += 4; break;
      default: ADD_FAILURE() << "unexpected wire type at " << at; return ends;
    }
    ends.insert(at);
  }
  return ends;
}

// ---- the sample maps ----

TEST(ApolloMapReader, ReadsEverySampleMapWithTheReadmeCounts) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  for (const SampleMap& sample : kSampleMaps) {
    for (const char* file_name : {"base_map.txt", "base_map.bin"}) {
      const fs::path file = apollo_dir() / sample.name / file_name;
      SCOPED_TRACE(file.string());
      const MapDescription map = read_apollo_map(file);
      EXPECT_EQ(map.name, sample.name);
      EXPECT_EQ(map.source, file.string());
      EXPECT_EQ(map.lanes.size(), sample.lanes);
      EXPECT_EQ(map.junctions.size(), sample.junctions);
      EXPECT_EQ(map.traffic_lights.size(), sample.signals);
      EXPECT_EQ(sign_count(map, SignKind::stop), sample.stop_signs);
      EXPECT_EQ(sign_count(map, SignKind::yield), 0u);
      EXPECT_EQ(map.crosswalks.size(), sample.crosswalks);
      EXPECT_FALSE(map.projection.empty());
      for (const LaneDescription& lane : map.lanes) {
        EXPECT_FALSE(lane.id.empty());
        EXPECT_GE(lane.centre_line.size(), 2u) << lane.id;
      }
      for (const TrafficLightDescription& light : map.traffic_lights)
        EXPECT_FALSE(light.plan.has_value()) << light.id;
    }
  }
}

TEST(ApolloMapReader, TextAndBinaryFormsReadTheSame) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  for (const SampleMap& sample : kSampleMaps) {
    SCOPED_TRACE(sample.name);
    const MapDescription text = read_apollo_map_text(apollo_dir() / sample.name / "base_map.txt");
    const MapDescription binary =
        read_apollo_map_binary(apollo_dir() / sample.name / "base_map.bin");
    EXPECT_EQ(map_difference(text, binary), "");
  }
}

// Facts read by hand from san_francisco/base_map.txt.
TEST(ApolloMapReader, SanFranciscoPinnedFacts) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  for (const char* file_name : {"base_map.txt", "base_map.bin"}) {
    SCOPED_TRACE(file_name);
    const MapDescription map = read_apollo_map(apollo_dir() / "san_francisco" / file_name);
    EXPECT_EQ(map.projection, kUtmZone10);

    const auto lane = std::find_if(map.lanes.begin(), map.lanes.end(),
                                   [](const LaneDescription& l) { return l.id == "lane_540"; });
    ASSERT_NE(lane, map.lanes.end());
    ASSERT_EQ(lane->centre_line.size(), 4u);
    EXPECT_EQ(lane->centre_line.front(), (MapPoint{553441.7675434585, 4182312.516265723}));
    EXPECT_EQ(lane->centre_line.back(), (MapPoint{553441.4518696304, 4182472.859222266}));
    EXPECT_EQ(lane->successors, (std::vector<std::string>{"lane_1450", "lane_1460"}));
    EXPECT_EQ(lane->predecessors, (std::vector<std::string>{"lane_1423", "lane_1429"}));
    EXPECT_EQ(lane->left_forward_neighbours, std::vector<std::string>{"lane_541"});
    EXPECT_TRUE(lane->right_forward_neighbours.empty());
    EXPECT_DOUBLE_EQ(lane->speed_limit, 11.175999641418457);
    EXPECT_EQ(lane->turn, LaneTurn::none);
    EXPECT_EQ(lane->left_boundary_type, BoundaryType::dotted_white);
    EXPECT_EQ(lane->right_boundary_type, BoundaryType::curb);
    EXPECT_FALSE(lane->left_boundary.empty());
    EXPECT_FALSE(lane->right_boundary.empty());
    EXPECT_EQ(lane->left_width, (std::vector<WidthSample>{{0.0, 1.75},
                                                          {88.09297943115234, 1.75},
                                                          {131.23635864257812, 1.75},
                                                          {160.34474182128906, 1.75}}));
    EXPECT_EQ(lane->right_width, lane->left_width);
    EXPECT_EQ(lane->junction, "");

    const TrafficLightDescription& signal = map.traffic_lights.front();
    EXPECT_EQ(signal.id, "signal_1");
    EXPECT_EQ(signal.heads,
              std::vector<MapPoint>(3, MapPoint{552893.6861454482, 4182871.813415381}));
    ASSERT_EQ(signal.stop_lines.size(), 1u);
    ASSERT_EQ(signal.stop_lines[0].size(), 5u);
    EXPECT_EQ(signal.stop_lines[0].front(), (MapPoint{552919.2929798599, 4182891.396179053}));
    // Its sixth overlap joins it to junction J_0, not to a lane.
    ASSERT_EQ(signal.lanes.size(), 5u);
    const char* const signal_lanes[] = {"lane_656", "lane_665", "lane_662", "lane_664", "lane_663"};
    for (std::size_t i = 0; i < 5; ++i) {
      EXPECT_EQ(signal.lanes[i].lane, signal_lanes[i]);
      EXPECT_EQ(signal.lanes[i].s_begin, 0.0);
      EXPECT_EQ(signal.lanes[i].s_end, 0.699999988079071);
    }

    const SignDescription& stop = map.signs.front();
    EXPECT_EQ(stop.id, "stopsign_0");
    EXPECT_EQ(stop.kind, SignKind::stop);
    ASSERT_EQ(stop.stop_lines.size(), 1u);
    EXPECT_EQ(stop.stop_lines[0], (std::vector<MapPoint>{{552841.375159883, 4182504.761352393},
                                                         {552837.4507748123, 4182504.7413977114},
                                                         {552833.4507709976, 4182504.739158484}}));
    ASSERT_EQ(stop.lanes.size(), 3u);
    EXPECT_EQ(stop.lanes[0].lane, "lane_695");
    EXPECT_EQ(stop.lanes[1].lane, "lane_700");
    EXPECT_EQ(stop.lanes[2].lane, "lane_53");

    // The first crosswalk has neither id nor overlaps; the second is CW_1.
    EXPECT_EQ(map.crosswalks[0].id, "");
    EXPECT_TRUE(map.crosswalks[0].lanes.empty());
    EXPECT_EQ(map.crosswalks[0].outline.size(), 4u);
    const CrosswalkDescription& crosswalk = map.crosswalks[1];
    EXPECT_EQ(crosswalk.id, "CW_1");
    EXPECT_EQ(crosswalk.outline.front(), (MapPoint{552849.219030046, 4182655.160217139}));
    ASSERT_EQ(crosswalk.lanes.size(), 7u);
    EXPECT_EQ(crosswalk.lanes[0].lane, "lane_738");
    EXPECT_EQ(crosswalk.lanes[0].s_begin, 25.90890121459961);
    EXPECT_EQ(crosswalk.lanes[0].s_end, 35.91410446166992);

    EXPECT_EQ(map.junctions.front().id, "J_0");
    EXPECT_EQ(map.junctions.front().outline.front(),
              (MapPoint{552906.5440250869, 4182900.464904639}));
  }
}

// ---- a small hand-written map: what the samples do not show ----

const char kSmallMap[] = R"(# a comment
header {
  version: "1"
  projection { proj: "+proj=utm +zone=32 +ellps=WGS84" }
  vendor: "scenfuzz test"
}
road { id { id: "road_1" } section { id { id: "1" } } }
lane {
  id { id: "a" }
  central_curve {
    segment { line_segment { point { x: 0 y: 0 z: 5 } point { x: 10 y: 0 } } s: 0 }
    segment { line_segment { point { x: 10 y: 0 } point { x: 20 y: 1 } } s: 10 }
  }
  left_boundary { curve { segment { line_segment { point { x: 0 y: 2 } point { x: 20 y: 3 } } } }
                  boundary_type { s: 0 types: SOLID_YELLOW types: CURB } virtual: false }
  speed_limit: 8.5
  overlap_id { id: "ov_yield_a" }
  successor_id { id: "b" }
  left_neighbor_reverse_lane_id { id: "r" }
  type: CITY_DRIVING
  turn: U_TURN
  direction: FORWARD
  junction_id { id: "J" }
  left_sample { s: 0 width: 1.5 }
  left_sample { s: 20 width: 1.6 }
  left_road_sample { s: 0 width: 4 }
  self_reverse_lane_id { id: "r" }
}
lane {
  id { id: "b" }
  central_curve { segment { line_segment { point { x: 20 y: 1 } point { x: 30 y: 1 } } } }
  predecessor_id { id: "a" }
  turn: LEFT_TURN
}
junction { id { id: "J" } polygon { point { x: -1 y: -1 } point { x: 21 y: -1 } point { x: 21 y: 4 } } }
yield {
  id { id: "Y" }
  stop_line { segment { line_segment { point { x: 15 y: -2 } point { x: 15 y: 2 } } } }
  overlap_id { id: "ov_yield_a" }
  overlap_id { id: "no_such_overlap" }
}
overlap {
  id { id: "ov_yield_a" }
  object { id { id: "a" } lane_overlap_info { start_s: 14.5 end_s: 15.5 is_merge: false } }
  object { id { id: "Y" } yield_sign_overlap_info { } }
}
clear_area { id { id: "C" } }
)";

TEST(ApolloMapReader, SmallTextMapSkipsUnknownFieldsAndJoinsCurveSegments) {
  const ScratchDir scratch;
  fs::create_directory(scratch.path() / "small");
  const fs::path file = scratch.write("small/base_map.txt", kSmallMap);
  const MapDescription map = read_apollo_map(file);
  EXPECT_EQ(map.name, "small");
  EXPECT_EQ(map.projection, "+proj=utm +zone=32 +ellps=WGS84");
  ASSERT_EQ(map.lanes.size(), 2u);

  const LaneDescription& a = map.lanes[0];
  EXPECT_EQ(a.id, "a");
  // The joint point (10, 0) is kept once; z is dropped.
  EXPECT_EQ(a.centre_line, (std::vector<MapPoint>{{0, 0}, {10, 0}, {20, 1}}));
  EXPECT_EQ(a.left_boundary, (std::vector<MapPoint>{{0, 2}, {20, 3}}));
  EXPECT_TRUE(a.right_boundary.empty());
  EXPECT_EQ(a.left_boundary_type, BoundaryType::solid_yellow);
  EXPECT_EQ(a.right_boundary_type, BoundaryType::unknown);
  EXPECT_EQ(a.left_width, (std::vector<WidthSample>{{0, 1.5}, {20, 1.6}}));
  EXPECT_TRUE(a.right_width.empty());
  EXPECT_EQ(a.speed_limit, 8.5);
  EXPECT_EQ(a.turn, LaneTurn::u_turn);
  EXPECT_EQ(a.successors, std::vector<std::string>{"b"});
  EXPECT_EQ(a.left_reverse_neighbours, std::vector<std::string>{"r"});
  EXPECT_EQ(a.junction, "J");
  EXPECT_EQ(map.lanes[1].turn, LaneTurn::left);
  EXPECT_EQ(map.lanes[1].speed_limit, 0.0);
  EXPECT_EQ(map.lanes[1].predecessors, std::vector<std::string>{"a"});

  ASSERT_EQ(map.junctions.size(), 1u);
  EXPECT_EQ(map.junctions[0].outline.size(), 3u);

  ASSERT_EQ(map.signs.size(), 1u);
  const SignDescription& yield = map.signs[0];
  EXPECT_EQ(yield.id, "Y");
  EXPECT_EQ(yield.kind, SignKind::yield);
  ASSERT_EQ(yield.stop_lines.size(), 1u);
  EXPECT_EQ(yield.stop_lines[0], (std::vector<MapPoint>{{15, -2}, {15, 2}}));
  // The unknown overlap is skipped.
  ASSERT_EQ(yield.lanes.size(), 1u);
  EXPECT_EQ(yield.lanes[0].lane, "a");
  EXPECT_EQ(yield.lanes[0].s_begin, 14.5);
  EXPECT_EQ(yield.lanes[0].s_end, 15.5);
}

// ---- malformed input ----

TEST(ApolloMapReaderMalformed, TextSyntaxErrorNamesFileLineAndColumn) {
  const ScratchDir scratch;
  const fs::path file = scratch.write("base_map.txt",
                                      "header {\n"
                                      "  projection { proj: \"x\" }\n"
                                      "}\n"
                                      "lane {\n"
                                      "  id { id: \"a\" }\n"
                                      "  speed_limit: fast\n"
                                      "}\n");
  const std::string message = map_error(read_apollo_map_text, file);
  EXPECT_NE(message.find(file.string() + ":6:"), std::string::npos) << message;
  EXPECT_NE(message.find("error:"), std::string::npos) << message;

  const fs::path unclosed = scratch.write("unclosed.txt", "lane {\n  id { id: \"a\" }\n");
  const std::string unclosed_message = map_error(read_apollo_map_text, unclosed);
  EXPECT_NE(unclosed_message.find(unclosed.string() + ":3:"), std::string::npos)
      << unclosed_message;

  // Protobuf places an unknown enum value at the token after it: keep that on the same line.
  const fs::path bad_enum =
      scratch.write("bad_enum.txt", "lane {\n  id { id: \"a\" }\n  turn: SIDEWAYS }\n");
  const std::string bad_enum_message = map_error(read_apollo_map_text, bad_enum);
  EXPECT_NE(bad_enum_message.find(bad_enum.string() + ":3:"), std::string::npos)
      << bad_enum_message;
}

TEST(ApolloMapReaderMalformed, LaneWithoutCentreLine) {
  const ScratchDir scratch;
  const fs::path no_curve = scratch.write("no_curve.txt", "lane { id { id: \"lane_7\" } }\n");
  EXPECT_NE(map_error(read_apollo_map_text, no_curve).find("lane_7"), std::string::npos);

  const fs::path one_point =
      scratch.write("one_point.txt",
                    "lane { id { id: \"lane_8\" } central_curve { segment { line_segment {\n"
                    "  point { x: 1 y: 2 } } } } }\n");
  EXPECT_NE(map_error(read_apollo_map_text, one_point).find("lane_8"), std::string::npos);

  const fs::path no_y =
      scratch.write("no_y.txt",
                    "lane { id { id: \"lane_9\" } central_curve { segment { line_segment {\n"
                    "  point { x: 1 y: 2 } point { x: 3 } } } } }\n");
  EXPECT_NE(map_error(read_apollo_map_text, no_y).find("lane_9"), std::string::npos);

  const fs::path no_id = scratch.write(
      "no_id.txt",
      "lane { central_curve { segment { line_segment { point { x: 1 y: 2 } point { x: 3 y: 4 } "
      "} } } }\n");
  map_error(read_apollo_map_text, no_id);
}

TEST(ApolloMapReaderMalformed, EmptyMissingAndDirectory) {
  const ScratchDir scratch;
  const fs::path empty_text = scratch.write("empty.txt", "");
  const fs::path empty_binary = scratch.write("empty.bin", "");
  const fs::path comment_only = scratch.write("comment.txt", "# nothing here\n");
  map_error(read_apollo_map_text, empty_text);
  map_error(read_apollo_map_binary, empty_binary);
  map_error(read_apollo_map_text, comment_only);

  const fs::path missing = scratch.path() / "missing" / "base_map.bin";
  map_error(read_apollo_map_text, missing);
  map_error(read_apollo_map_binary, missing);
  map_error(read_apollo_map, missing);

  map_error(read_apollo_map_text, scratch.path());
  map_error(read_apollo_map_binary, scratch.path());
}

TEST(ApolloMapReaderMalformed, TruncatedBinaryMap) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const std::string bytes = read_all(apollo_dir() / "borregas_ave" / "base_map.bin");
  ASSERT_GT(bytes.size(), 10000u);
  const std::set<std::size_t> field_ends = top_level_field_ends(bytes);
  ASSERT_EQ(*field_ends.rbegin(), bytes.size());

  std::vector<std::size_t> cuts = {1, 2, 3, 5, 10, 100, 1000, bytes.size() / 2, bytes.size() - 1};
  for (std::size_t cut = 7; cut < bytes.size(); cut += 1733) cuts.push_back(cut);
  // Cuts on a field boundary leave a valid smaller map; they must not crash, and the few of them
  // before the first lane must still fail for want of lanes.
  for (const std::size_t end : field_ends)
    if (end < bytes.size()) cuts.push_back(end);

  const ScratchDir scratch;
  std::size_t inside_fields = 0;
  for (const std::size_t cut : cuts) {
    SCOPED_TRACE("first " + std::to_string(cut) + " bytes");
    const fs::path file =
        scratch.write("cut_" + std::to_string(cut) + ".bin", bytes.substr(0, cut));
    if (field_ends.count(cut) == 0) {
      ++inside_fields;
      const std::string message = map_error(read_apollo_map_binary, file);
      EXPECT_NE(message.find("not a valid binary apollo.hdmap.Map"), std::string::npos) << message;
    } else {
      try {
        const MapDescription map = read_apollo_map_binary(file);
        EXPECT_FALSE(map.lanes.empty());
      } catch (const MapError& error) {
        EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos);
      }
    }
  }
  EXPECT_GE(inside_fields, 50u);
}

TEST(ApolloMapReaderMalformed, GarbageBytes) {
  const ScratchDir scratch;
  std::mt19937 random(20240611);
  std::uniform_int_distribution<int> byte(0, 255);
  for (const std::size_t size : {1u, 2u, 7u, 64u, 1000u, 100000u}) {
    for (int round = 0; round < 5; ++round) {
      std::string bytes(size, '\0');
      for (char& c : bytes) c = static_cast<char>(byte(random));
      const fs::path file = scratch.write(
          "garbage_" + std::to_string(size) + "_" + std::to_string(round) + ".bin", bytes);
      SCOPED_TRACE(file.string());
      map_error(read_apollo_map_binary, file);
      map_error(read_apollo_map_text, file);
    }
  }
}

TEST(ApolloMapReaderMalformed, WrongFormat) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const ScratchDir scratch;
  for (const char* name : {"wide_flat_map", "borregas_ave"}) {
    SCOPED_TRACE(name);
    // The binary reader given text: must fail, not read garbage. Copied so that the extension
    // does not pick the reader.
    const fs::path text = scratch.write(std::string(name) + "_text.bin",
                                        read_all(apollo_dir() / name / "base_map.txt"));
    const std::string message = map_error(read_apollo_map_binary, text);
    EXPECT_NE(message.find("not a valid binary apollo.hdmap.Map"), std::string::npos) << message;
    EXPECT_NE(map_error(read_apollo_map, text).find(text.string()), std::string::npos);

    map_error(read_apollo_map_text, apollo_dir() / name / "base_map.bin");
  }
}

}  // namespace
}  // namespace scenfuzz
