// What a map source says, before it is checked and indexed: lanes and road furniture that refer to
// each other by id, exactly as an Apollo HD map does. Map readers (Apollo text and binary) and the
// built-in map generators produce a MapDescription; build_road_map turns it into a RoadMap.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "physics/map/map_point.hpp"

namespace scenfuzz {

enum class LaneTurn { none, left, right, u_turn };

// Apollo's LaneBoundaryType. Whether a lane change across a boundary is allowed depends on it.
enum class BoundaryType {
  unknown,
  dotted_yellow,
  dotted_white,
  solid_yellow,
  solid_white,
  double_yellow,
  curb,
};

// Lane width on one side of the centre line, sampled along it (Apollo's left_sample/right_sample).
struct WidthSample {
  double s = 0;
  double width = 0;  // metres from the centre line to the boundary on that side

  bool operator==(const WidthSample&) const = default;
};

// The width at s: linear between samples, constant beyond the first and last. Needs a sample.
double width_at(const std::vector<WidthSample>& samples, double s);

struct LaneDescription {
  std::string id;
  std::vector<MapPoint> centre_line;  // in the direction of travel, at least two points
  // Optional: drawn when present; widths are derived from them when no samples are given.
  std::vector<MapPoint> left_boundary;
  std::vector<MapPoint> right_boundary;
  std::vector<WidthSample> left_width;  // empty: half of `default_width`
  std::vector<WidthSample> right_width;
  BoundaryType left_boundary_type = BoundaryType::unknown;
  BoundaryType right_boundary_type = BoundaryType::unknown;
  double speed_limit = 0;  // m/s; 0 when the source gives none
  LaneTurn turn = LaneTurn::none;
  std::vector<std::string> successors;
  std::vector<std::string> predecessors;
  std::vector<std::string> left_forward_neighbours;  // same direction, to the left
  std::vector<std::string> right_forward_neighbours;
  std::vector<std::string> left_reverse_neighbours;  // opposite direction, to the left
  std::vector<std::string> right_reverse_neighbours;
  std::string junction;  // id of the junction the lane lies in; empty outside junctions
};

struct JunctionDescription {
  std::string id;
  std::vector<MapPoint> outline;  // polygon
};

// Where a sign, signal or crosswalk meets a lane: the interval [s_begin, s_end] of the lane's
// centre line it covers (Apollo's lane overlap; a stop line gives s_begin == s_end or close).
struct LaneCrossingDescription {
  std::string lane;
  double s_begin = 0;
  double s_end = 0;
};

enum class SignalColour { red, yellow, green };

// One step of a fixed-time signal plan.
struct SignalPhase {
  SignalColour colour = SignalColour::red;
  double duration = 0;  // seconds

  bool operator==(const SignalPhase&) const = default;
};

// A fixed-time plan: the phases repeat with period sum(durations); `offset` shifts the cycle
// start, so at time t the signal shows the phase containing (t + offset) mod period.
struct SignalPlan {
  std::vector<SignalPhase> phases;
  double offset = 0;

  bool operator==(const SignalPlan&) const = default;
};

struct TrafficLightDescription {
  std::string id;
  std::vector<MapPoint> heads;                    // where the signal heads stand
  std::vector<std::vector<MapPoint>> stop_lines;  // each a polyline across the controlled lanes
  std::vector<LaneCrossingDescription> lanes;     // controlled lanes, at their stop lines
  std::optional<SignalPlan> plan;                 // built-in maps have one; Apollo maps do not
};

enum class SignKind { stop, yield };

struct SignDescription {
  std::string id;
  SignKind kind = SignKind::stop;
  std::vector<std::vector<MapPoint>> stop_lines;
  std::vector<LaneCrossingDescription> lanes;
};

struct CrosswalkDescription {
  std::string id;
  std::vector<MapPoint> outline;               // polygon
  std::vector<LaneCrossingDescription> lanes;  // lanes it crosses and where
  std::optional<SignalPlan> walk_plan;         // pedestrian signal: green = walk
};

// A lane that junctions cut into pieces, kept under its own id so that a position written on it
// (CH-Scenario's `<road>_f0`, physics/map/outline_map.hpp) finds its place: its pieces in driving
// order, each with the arc length along the whole lane at which it begins (a stretch dropped
// where the road ends inside a junction lies between none).
struct LaneChainPiece {
  std::string lane;
  double start = 0;
};

struct LaneChainDescription {
  std::string id;
  std::vector<LaneChainPiece> pieces;
};

// The map header's geo-reference: a PROJ string such as
// "+proj=utm +zone=10 +ellps=WGS84 +datum=WGS84 +units=m +no_defs". Empty for built-in maps.
struct MapDescription {
  std::string name;
  std::string source;  // file path, or "built-in" for generated maps
  std::string projection;
  double default_lane_width = 3.5;  // for lanes with neither width samples nor boundaries
  std::vector<LaneDescription> lanes;
  std::vector<JunctionDescription> junctions;
  std::vector<TrafficLightDescription> traffic_lights;
  std::vector<SignDescription> signs;
  std::vector<CrosswalkDescription> crosswalks;
  std::vector<LaneChainDescription> lane_chains;
};

}  // namespace scenfuzz
