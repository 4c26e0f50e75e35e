// The ego's route as a path to follow: the drivable path along its lane route, how far along it
// the ego has come, the traffic lights, signs and crosswalks on it, the speed limit at each
// point, and where other objects lie relative to it. Shared by the reference driver and by
// what a plugin driver is told.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "physics/actors/trajectory.hpp"
#include "physics/map/junction_stretch.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/polyline.hpp"
#include "physics/map/polyline_boxes.hpp"
#include "physics/map/road_map.hpp"
#include "physics/map/segment_frames.hpp"

namespace scenfuzz {

// A light, sign or crosswalk on the route, at arc length `s` of the path (where it begins).
struct RouteFeature {
  FeatureKind kind = FeatureKind::traffic_light;
  std::uint32_t index = 0;  // into the map's traffic_lights(), signs() or crosswalks()
  double s = 0;
  double s_end = 0;
};

// Which lane of the route the path follows at some arc length, and where on that lane.
struct RouteLanePosition {
  LaneIndex lane = 0;
  double lane_s = 0;    // arc length on the lane's centre line
  double lane_end = 0;  // path arc length where the route leaves this lane
};

// Where a point lies along the path: arc length and signed lateral offset (left positive).
// The stretch of path segments locate() searches, found once for the many objects of a step.
struct PathWindow {
  std::size_t first = 0, last = 0;  // segments
};

struct PathCoordinate {
  double s = 0;
  double lateral = 0;
  bool beyond_end = false;  // past either end of the stretch searched: s is that end's
  std::size_t segment = 0;  // the path segment s lies on (a hint for heading_at)
};

class RouteTracker {
 public:
  // `speed_limits` override the map's limit on the lanes they name; `default_speed_limit`
  // stands in for lanes without one.
  RouteTracker(const RoadMap& map, const LaneRoute& route,
               std::span<const std::pair<LaneIndex, double>> speed_limits,
               double default_speed_limit);

  // Moves the progress to the projection of `point` near where it was.
  void update(MapPoint point);

  const Polyline& path() const { return path_; }
  double progress() const { return progress_; }
  // The unit direction of the path's segment at the progress (not for an empty route).
  MapPoint direction() const { return frames_.direction(segment_); }
  double length() const { return path_.length(); }
  bool empty() const { return path_.points().size() < 2; }
  const std::vector<RouteFeature>& features() const { return features_; }
  // Where the path moves from one lane to the next, in path arc length, in order.
  const std::vector<LaneChangeStretch>& lane_changes() const { return lane_changes_; }
  double speed_limit_at(double s) const;
  // The route lane at path arc length s (nullopt for an empty route). Inside a lane change
  // stretch the path lies between two lanes; this is the lane the route is on at s.
  std::optional<RouteLanePosition> lane_at(double s) const;
  // path().segment_at(s) of s clamped to the path: walked to from the progress's segment when s
  // lies a few metres from it (the driver's aim and the lanes beside it are looked up there).
  std::size_t segment_at(double s) const;
  // path().heading_at(s), from headings computed once (the driver asks for several a step).
  double heading_at(double s) const;
  // The same, walking from segment `hint` (a located coordinate's) instead of a binary search.
  double heading_at(double s, std::size_t hint) const;
  // The path's curvature (1/m, unsigned) around arc length s.
  double curvature_at(double s) const;
  // The same, walking from segment `hint` instead of a binary search.
  double curvature_at(double s, std::size_t hint) const;
  // The route's stretch through the junction it is in at path arc length s, or the next ahead.
  std::optional<JunctionStretch> junction_ahead(double s) const;
  const std::vector<RouteSegment>& segments() const { return segments_; }

  // Where `point` lies on the path between progress - behind and progress + ahead, or nullopt
  // when it is nearer to no point of that stretch than `max_lateral`.
  std::optional<PathCoordinate> locate(MapPoint point, double behind, double ahead,
                                       double max_lateral) const;
  // The same in two parts: the stretch (valid until the progress moves), then a point in it.
  PathWindow window(double behind, double ahead) const;
  std::optional<PathCoordinate> locate(MapPoint point, PathWindow window, double max_lateral) const;
  // Whether `point` is surely farther than `distance` from every segment of the stretch (from
  // bounding boxes of runs of segments, up to rounding far below a micrometre): then locate finds
  // it nowhere nearer, and a caller that would reject it as too far aside need not locate it.
  bool surely_farther(MapPoint point, PathWindow window, double distance) const;

 private:
  std::size_t segment_near(double s, std::size_t hint) const;

  Polyline path_;
  std::vector<RouteFeature> features_;
  std::vector<LaneChangeStretch> lane_changes_;
  std::vector<double> limit_s_, limit_speed_;  // speed limit from each s on (one per segment)
  std::vector<RouteSegment> segments_;         // the route's, in the order of limit_s_
  std::vector<JunctionStretch> junctions_;     // the route's stretches through junctions
  std::vector<double> curvature_;              // per path vertex
  std::vector<double> headings_;               // per path segment
  SegmentFrames frames_;                       // of path segments, for locate's projections
  PolylineBoxes boxes_;                        // of runs of path segments, for surely_farther
  std::size_t segment_ = 0;
  double progress_ = 0;
  // window()'s last answer for each of a few `behind` values (its callers ask with the same ones
  // at every step, and progress moves by a segment or two): the next walks from it instead of
  // binary-searching the path (segment_walk.hpp, the same answer). A cache of a const query, so
  // a tracker is for one thread, as each driver's is.
  struct WindowHint {
    double behind = -1;  // none yet
    PathWindow window;
  };
  mutable std::array<WindowHint, 3> window_hints_{};
  mutable std::size_t next_hint_ = 0;  // the slot a new `behind` takes
};

}  // namespace scenfuzz
