// A checked, indexed road map: lanes with their geometry and connections resolved to indices,
// road furniture attached to the lanes it meets, and a spatial index over lane segments.
// Built only by build_road_map, which keeps these invariants:
//   - every lane has a centre line of positive length, and widths on both sides;
//   - every index stored in a lane or a crossing is a valid index into this map;
//   - each lane's `features` are sorted by s_begin.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "physics/map/map_description.hpp"
#include "physics/map/polyline.hpp"

namespace scenfuzz {

using LaneIndex = std::uint32_t;

// Bad map input: the message names the file (and the line, for text) and what was wrong.
class MapError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class FeatureKind { traffic_light, stop_sign, yield_sign, crosswalk };

// Something on a lane a driver must react to, at [s_begin, s_end] on the lane's centre line.
// `index` points into RoadMap::traffic_lights(), signs() or crosswalks(), by kind.
struct LaneFeature {
  FeatureKind kind = FeatureKind::traffic_light;
  std::uint32_t index = 0;
  double s_begin = 0;
  double s_end = 0;
};

struct LaneCrossing {
  LaneIndex lane = 0;
  double s_begin = 0;
  double s_end = 0;
};

struct Lane {
  std::string id;
  Polyline centre_line;
  std::vector<WidthSample> left_width;   // never empty
  std::vector<WidthSample> right_width;  // never empty
  std::vector<MapPoint> left_boundary;   // as given, or offset from the centre line
  std::vector<MapPoint> right_boundary;
  BoundaryType left_boundary_type = BoundaryType::unknown;
  BoundaryType right_boundary_type = BoundaryType::unknown;
  double speed_limit = 0;
  LaneTurn turn = LaneTurn::none;
  std::vector<LaneIndex> successors;
  std::vector<LaneIndex> predecessors;
  std::vector<LaneIndex> left_forward_neighbours;
  std::vector<LaneIndex> right_forward_neighbours;
  std::vector<LaneIndex> left_reverse_neighbours;
  std::vector<LaneIndex> right_reverse_neighbours;
  std::optional<std::uint32_t> junction;
  std::vector<LaneFeature> features;
  // The narrowest of left_width and of right_width (build_road_map finds them).
  double narrowest_left_width = 0;
  double narrowest_right_width = 0;

  double length() const { return centre_line.length(); }
};

struct Junction {
  std::string id;
  std::vector<MapPoint> outline;
  std::vector<LaneIndex> lanes;  // its lanes, ascending (build_road_map finds them)
};

struct TrafficLight {
  std::string id;
  std::vector<MapPoint> heads;
  std::vector<std::vector<MapPoint>> stop_lines;
  std::vector<LaneCrossing> lanes;
  std::optional<SignalPlan> plan;
};

struct Sign {
  std::string id;
  SignKind kind = SignKind::stop;
  std::vector<std::vector<MapPoint>> stop_lines;
  std::vector<LaneCrossing> lanes;
};

struct Crosswalk {
  std::string id;
  std::vector<MapPoint> outline;
  std::vector<LaneCrossing> lanes;
  std::optional<SignalPlan> walk_plan;
};

// A place along a lane, as find_lane_station gives it.
struct LaneStation {
  LaneIndex lane = 0;
  double s = 0;
};

struct MapBounds {
  MapPoint min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  MapPoint max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  void include(MapPoint p);
  bool empty() const { return min.x > max.x; }
};

class JunctionConflicts;
struct ConflictPoint;
class LaneSegmentIndex;

class RoadMap {
 public:
  RoadMap(RoadMap&&) noexcept;
  RoadMap& operator=(RoadMap&&) noexcept;
  ~RoadMap();

  const std::string& name() const { return name_; }
  const std::string& source() const { return source_; }
  const std::string& projection() const { return projection_; }
  const std::vector<Lane>& lanes() const { return lanes_; }
  const Lane& lane(LaneIndex index) const { return lanes_[index]; }
  const std::vector<Junction>& junctions() const { return junctions_; }
  const std::vector<TrafficLight>& traffic_lights() const { return traffic_lights_; }
  const std::vector<Sign>& signs() const { return signs_; }
  const std::vector<Crosswalk>& crosswalks() const { return crosswalks_; }
  const MapBounds& bounds() const { return bounds_; }
  // References to ids the map does not have, dropped while building (real maps have some).
  const std::vector<std::string>& warnings() const { return warnings_; }

  std::optional<LaneIndex> find_lane(std::string_view id) const;
  // Where arc length `s` along lane or lane chain `id` lies (MapDescription::lane_chains): a
  // lane's own s, or the chain's piece holding s and the s on it (the first piece for s before
  // it, the piece beginning last at or before s otherwise; the caller clamps). None for an id
  // that names neither.
  std::optional<LaneStation> find_lane_station(std::string_view id, double s) const;
  std::size_t stop_sign_count() const;
  std::size_t yield_sign_count() const;

  const LaneSegmentIndex& segment_index() const { return *segment_index_; }

  // The widest half of any lane (left or right of its centre line): no point of a lane is
  // farther from its centre line.
  double widest_half_lane() const { return widest_half_lane_; }
  // The lanes crossing or merging with junction lane `lane` (conflicting_lanes,
  // lane_conflicts.hpp), found at the first call for it and kept for every simulation on the map;
  // safe to call from several threads at once.
  const std::vector<LaneIndex>& junction_conflicts(LaneIndex lane) const;
  // Where junction lane `lane` meets them (conflict_points), kept the same way.
  const std::vector<ConflictPoint>& junction_conflict_points(LaneIndex lane) const;

 private:
  friend RoadMap build_road_map(MapDescription description);
  RoadMap();

  std::string name_;
  std::string source_;
  std::string projection_;
  std::vector<Lane> lanes_;
  std::vector<Junction> junctions_;
  std::vector<TrafficLight> traffic_lights_;
  std::vector<Sign> signs_;
  std::vector<Crosswalk> crosswalks_;
  MapBounds bounds_;
  std::vector<std::string> warnings_;
  std::unordered_map<std::string, LaneIndex> lane_by_id_;
  struct ChainPiece {
    LaneIndex lane = 0;
    double start = 0;
  };
  std::unordered_map<std::string, std::vector<ChainPiece>> chains_;
  std::unique_ptr<LaneSegmentIndex> segment_index_;
  double widest_half_lane_ = 0;
  std::unique_ptr<JunctionConflicts> conflicts_;
};

// Checks and indexes a description. Throws MapError (naming description.source) for what cannot
// be repaired: no lanes, duplicate lane ids, a lane without a usable centre line. References to
// unknown lanes and crossings outside a lane are dropped with a warning.
RoadMap build_road_map(MapDescription description);

}  // namespace scenfuzz
