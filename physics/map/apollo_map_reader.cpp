// Apollo HD map reader: parses base_map.txt / base_map.bin with the schema subset in
// apollo_map.proto, then turns the apollo.hdmap.Map into a MapDescription. Signals, signs and
// crosswalks find the lanes they meet through the overlaps they list, as Apollo's own map loader
// does: an overlap's lane object carries the lane's [start_s, end_s].
#include "physics/map/apollo_map_reader.hpp"

#include <google/protobuf/arena.h>
#include <google/protobuf/io/tokenizer.h>
#include <google/protobuf/text_format.h>

#include <climits>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <utility>
#include <vector>

#include "physics/map/apollo_map.pb.h"  // generated from apollo_map.proto (physics/CMakeLists.txt)
#include "physics/map/road_map.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
namespace hd = apollo::hdmap;
using google::protobuf::RepeatedPtrField;

[[noreturn]] void fail(const fs::path& file, std::string_view what) {
  std::string message = file.string();
  message += ": ";
  message += what;
  throw MapError(message);
}

std::string read_bytes(const fs::path& file) {
  std::error_code error;
  const fs::file_status status = fs::status(file, error);
  if (error) fail(file, "cannot read the map: " + error.message());
  if (fs::is_directory(status)) fail(file, "cannot read the map: it is a directory, not a file");
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, "cannot open the map for reading");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) fail(file, "cannot read the map: its size is unknown");
  in.seekg(0, std::ios::beg);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (!in.read(bytes.data(), static_cast<std::streamsize>(size)))
    fail(file, "cannot read the map: read error");
  return bytes;
}

// Keeps protobuf's first error; its line and column are 0-based.
class FirstErrorCollector : public google::protobuf::io::ErrorCollector {
 public:
  void AddError(int line, google::protobuf::io::ColumnNumber column,
                const std::string& message) override {
    if (has_error_) return;
    has_error_ = true;
    line_ = line;
    column_ = column;
    message_ = message;
  }
  // Unknown fields are reported as warnings; they are expected (the schema is a subset).
  void AddWarning(int, google::protobuf::io::ColumnNumber, const std::string&) override {}

  bool has_error() const { return has_error_; }
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& message() const { return message_; }

 private:
  bool has_error_ = false;
  int line_ = 0;
  int column_ = 0;
  std::string message_;
};

LaneTurn to_turn(hd::Lane::LaneTurn turn) {
  switch (turn) {
    case hd::Lane::LEFT_TURN: return LaneTurn::left;
    case hd::Lane::RIGHT_TURN: return LaneTurn::right;
    case hd::Lane::U_TURN: return LaneTurn::u_turn;
    case hd::Lane::NO_TURN: return LaneTurn::none;
  }
  return LaneTurn::none;
}

BoundaryType to_boundary_type(const hd::LaneBoundary& boundary) {
  if (boundary.boundary_type_size() == 0 || boundary.boundary_type(0).types_size() == 0)
    return BoundaryType::unknown;
  switch (boundary.boundary_type(0).types(0)) {
    case hd::LaneBoundaryType::DOTTED_YELLOW: return BoundaryType::dotted_yellow;
    case hd::LaneBoundaryType::DOTTED_WHITE: return BoundaryType::dotted_white;
    case hd::LaneBoundaryType::SOLID_YELLOW: return BoundaryType::solid_yellow;
    case hd::LaneBoundaryType::SOLID_WHITE: return BoundaryType::solid_white;
    case hd::LaneBoundaryType::DOUBLE_YELLOW: return BoundaryType::double_yellow;
    case hd::LaneBoundaryType::CURB: return BoundaryType::curb;
    case hd::LaneBoundaryType::UNKNOWN: return BoundaryType::unknown;
  }
  return BoundaryType::unknown;
}

std::vector<std::string> to_ids(const RepeatedPtrField<hd::Id>& ids) {
  std::vector<std::string> result;
  result.reserve(static_cast<std::size_t>(ids.size()));
  for (const hd::Id& id : ids) result.push_back(id.id());
  return result;
}

std::vector<WidthSample> to_widths(const RepeatedPtrField<hd::LaneSampleAssociation>& samples) {
  std::vector<WidthSample> result;
  result.reserve(static_cast<std::size_t>(samples.size()));
  for (const hd::LaneSampleAssociation& sample : samples)
    result.push_back({sample.s(), sample.width()});
  return result;
}

// Converts one parsed map; every error names the file and the object it was found in.
class Converter {
 public:
  Converter(const hd::Map& map, const fs::path& file) : map_(map), file_(file) {
    overlap_by_id_.reserve(static_cast<std::size_t>(map.overlap_size()));
    for (const hd::Overlap& overlap : map.overlap())
      overlap_by_id_.emplace(overlap.id().id(), &overlap);
  }

  MapDescription convert() const {
    MapDescription description;
    description.source = file_.string();
    description.name = folder_name();
    description.projection = map_.header().projection().proj();

    description.lanes.reserve(static_cast<std::size_t>(map_.lane_size()));
    for (int i = 0; i < map_.lane_size(); ++i) description.lanes.push_back(lane(map_.lane(i), i));
    assign_junctions_from_roads(description.lanes);

    description.junctions.reserve(static_cast<std::size_t>(map_.junction_size()));
    for (const hd::Junction& junction : map_.junction())
      description.junctions.push_back(
          {junction.id().id(), polygon(junction.polygon(), "junction", junction.id())});

    description.traffic_lights.reserve(static_cast<std::size_t>(map_.signal_size()));
    for (const hd::Signal& signal : map_.signal())
      description.traffic_lights.push_back(light(signal));

    description.signs.reserve(static_cast<std::size_t>(map_.stop_sign_size() + map_.yield_size()));
    for (const hd::StopSign& sign : map_.stop_sign()) {
      SignDescription& stop = description.signs.emplace_back();
      stop.id = sign.id().id();
      stop.kind = SignKind::stop;
      for (const hd::Curve& line : sign.stop_line())
        add_stop_line(line, "stop sign", sign.id(), stop.stop_lines);
      stop.lanes = lane_crossings(sign.overlap_id());
    }
    for (const hd::YieldSign& sign : map_.yield()) {
      SignDescription& yield = description.signs.emplace_back();
      yield.id = sign.id().id();
      yield.kind = SignKind::yield;
      for (const hd::Curve& line : sign.stop_line())
        add_stop_line(line, "yield sign", sign.id(), yield.stop_lines);
      yield.lanes = lane_crossings(sign.overlap_id());
    }

    description.crosswalks.reserve(static_cast<std::size_t>(map_.crosswalk_size()));
    for (const hd::Crosswalk& crosswalk : map_.crosswalk()) {
      CrosswalkDescription& walk = description.crosswalks.emplace_back();
      walk.id = crosswalk.id().id();
      walk.outline = polygon(crosswalk.polygon(), "crosswalk", crosswalk.id());
      walk.lanes = lane_crossings(crosswalk.overlap_id());
    }
    return description;
  }

 private:
  // A lane without its own junction_id takes that of the road whose section lists it.
  void assign_junctions_from_roads(std::vector<LaneDescription>& lanes) const {
    std::unordered_map<std::string, std::string> junction_of_lane;
    for (const hd::Road& road : map_.road()) {
      if (road.junction_id().id().empty()) continue;
      for (const hd::RoadSection& section : road.section())
        for (const hd::Id& lane : section.lane_id())
          junction_of_lane.emplace(lane.id(), road.junction_id().id());
    }
    for (LaneDescription& lane : lanes) {
      if (!lane.junction.empty()) continue;
      auto found = junction_of_lane.find(lane.id);
      if (found != junction_of_lane.end()) lane.junction = found->second;
    }
  }

  std::string folder_name() const {
    fs::path folder = file_.parent_path();
    if (folder.empty()) {
      std::error_code ignored;
      folder = fs::current_path(ignored);
    }
    return folder.filename().string();
  }

  [[noreturn]] void fail_in(std::string_view kind, const hd::Id& id, std::string_view what) const {
    std::string message(kind);
    message += id.id().empty() ? std::string(" without id") : " \"" + id.id() + "\"";
    message += ": ";
    message += what;
    fail(file_, message);
  }

  // Apollo leaves x and y NaN when absent: such a point cannot be placed, so the map is rejected.
  MapPoint point(const hd::PointENU& p, std::string_view kind, const hd::Id& owner) const {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      fail_in(kind, owner, "a point has no finite x and y");
    return {p.x(), p.y()};
  }

  std::vector<MapPoint> polygon(const hd::Polygon& polygon, std::string_view kind,
                                const hd::Id& owner) const {
    std::vector<MapPoint> result;
    result.reserve(static_cast<std::size_t>(polygon.point_size()));
    for (const hd::PointENU& p : polygon.point()) result.push_back(point(p, kind, owner));
    return result;
  }

  // Consecutive segments share their joint point; it is kept once.
  std::vector<MapPoint> curve(const hd::Curve& curve, std::string_view kind,
                              const hd::Id& owner) const {
    std::size_t count = 0;
    for (const hd::CurveSegment& segment : curve.segment())
      count += static_cast<std::size_t>(segment.line_segment().point_size());
    std::vector<MapPoint> result;
    result.reserve(count);
    for (const hd::CurveSegment& segment : curve.segment()) {
      const auto& points = segment.line_segment().point();
      for (int i = 0; i < points.size(); ++i) {
        const MapPoint p = point(points[i], kind, owner);
        if (i == 0 && !result.empty() && result.back() == p) continue;
        result.push_back(p);
      }
    }
    return result;
  }

  void add_stop_line(const hd::Curve& line, std::string_view kind, const hd::Id& owner,
                     std::vector<std::vector<MapPoint>>& stop_lines) const {
    std::vector<MapPoint> points = curve(line, kind, owner);
    if (!points.empty()) stop_lines.push_back(std::move(points));
  }

  // The lanes among the objects of the listed overlaps. Overlap ids the map does not define are
  // skipped: real maps have a few, and nothing can be attached through them.
  std::vector<LaneCrossingDescription> lane_crossings(
      const RepeatedPtrField<hd::Id>& overlap_ids) const {
    std::vector<LaneCrossingDescription> result;
    for (const hd::Id& overlap_id : overlap_ids) {
      const auto found = overlap_by_id_.find(overlap_id.id());
      if (found == overlap_by_id_.end()) continue;
      for (const hd::ObjectOverlapInfo& object : found->second->object()) {
        if (!object.has_lane_overlap_info()) continue;
        const hd::LaneOverlapInfo& info = object.lane_overlap_info();
        result.push_back({object.id().id(), info.start_s(), info.end_s()});
      }
    }
    return result;
  }

  LaneDescription lane(const hd::Lane& lane, int index) const {
    if (lane.id().id().empty())
      fail(file_, "lane #" + std::to_string(index + 1) + " of the map has no id");
    LaneDescription result;
    result.id = lane.id().id();
    result.centre_line = curve(lane.central_curve(), "lane", lane.id());
    if (result.centre_line.size() < 2)
      fail_in("lane", lane.id(),
              "its central_curve has " + std::to_string(result.centre_line.size()) +
                  " distinct point(s); a lane needs at least two");
    result.left_boundary = curve(lane.left_boundary().curve(), "lane", lane.id());
    result.right_boundary = curve(lane.right_boundary().curve(), "lane", lane.id());
    result.left_width = to_widths(lane.left_sample());
    result.right_width = to_widths(lane.right_sample());
    result.left_boundary_type = to_boundary_type(lane.left_boundary());
    result.right_boundary_type = to_boundary_type(lane.right_boundary());
    result.speed_limit = lane.speed_limit();
    result.turn = to_turn(lane.turn());
    result.successors = to_ids(lane.successor_id());
    result.predecessors = to_ids(lane.predecessor_id());
    result.left_forward_neighbours = to_ids(lane.left_neighbor_forward_lane_id());
    result.right_forward_neighbours = to_ids(lane.right_neighbor_forward_lane_id());
    result.left_reverse_neighbours = to_ids(lane.left_neighbor_reverse_lane_id());
    result.right_reverse_neighbours = to_ids(lane.right_neighbor_reverse_lane_id());
    result.junction = lane.junction_id().id();
    return result;
  }

  TrafficLightDescription light(const hd::Signal& signal) const {
    TrafficLightDescription result;
    result.id = signal.id().id();
    for (const hd::Subsignal& head : signal.subsignal())
      if (head.has_location())
        result.heads.push_back(point(head.location(), "signal", signal.id()));
    for (const hd::Curve& line : signal.stop_line())
      add_stop_line(line, "signal", signal.id(), result.stop_lines);
    result.lanes = lane_crossings(signal.overlap_id());
    return result;
  }

  const hd::Map& map_;
  const fs::path& file_;
  std::unordered_map<std::string_view, const hd::Overlap*> overlap_by_id_;
};

}  // namespace

MapDescription read_apollo_map_text(const fs::path& file) {
  const std::string text = read_bytes(file);
  if (text.size() > static_cast<std::size_t>(INT_MAX)) fail(file, "the map is too large (> 2 GiB)");

  google::protobuf::Arena arena;  // one release for the whole message tree: parsing is faster
  hd::Map* map = google::protobuf::Arena::CreateMessage<hd::Map>(&arena);
  FirstErrorCollector errors;
  google::protobuf::TextFormat::Parser parser;
  parser.RecordErrorsTo(&errors);
  parser.AllowUnknownField(true);  // the schema is a subset of Apollo's
  if (!parser.ParseFromString(text, map)) {
    if (!errors.has_error()) fail(file, "error: not a valid text apollo.hdmap.Map");
    // The compiler-style "file:line:column: error: message", 1-based like editors count.
    throw MapError(file.string() + ":" + std::to_string(errors.line() + 1) + ":" +
                   std::to_string(errors.column() + 1) + ": error: " + errors.message());
  }
  if (map->lane_size() == 0) fail(file, "error: the map has no lanes");
  return Converter(*map, file).convert();
}

// Binary protobuf has no framing to tell a map from other bytes: a file of text, an empty file
// or a prefix cut on a field boundary may all parse. A map must therefore also have lanes, and
// every lane an id and a centre line (checked while converting), which a parse of foreign bytes
// almost never produces; a map that passes is as plausible as one can tell.
MapDescription read_apollo_map_binary(const fs::path& file) {
  const std::string bytes = read_bytes(file);
  if (bytes.empty()) fail(file, "not a valid binary apollo.hdmap.Map: the file is empty");
  if (bytes.size() > static_cast<std::size_t>(INT_MAX))
    fail(file, "the map is too large (> 2 GiB)");

  google::protobuf::Arena arena;
  hd::Map* map = google::protobuf::Arena::CreateMessage<hd::Map>(&arena);
  if (!map->ParseFromArray(bytes.data(), static_cast<int>(bytes.size())))
    fail(file, "not a valid binary apollo.hdmap.Map (truncated or not a map)");
  if (map->lane_size() == 0) fail(file, "not a valid binary apollo.hdmap.Map: it has no lanes");
  return Converter(*map, file).convert();
}

MapDescription read_apollo_map(const fs::path& file) {
  if (file.extension() == ".txt") return read_apollo_map_text(file);
  return read_apollo_map_binary(file);
}

}  // namespace scenfuzz
