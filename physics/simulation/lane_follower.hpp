// A reactive NPC on the lanes, as simulator NPCs drive (LGSVL's and CARLA's): it follows its lane
// route at its desired speed, slows for bends, follows whatever is ahead in its path (the ego
// included) with the Intelligent Driver Model, stops for red lights and at stop signs, gives way
// at stop and yield signs to crossing traffic, and stops for pedestrians on or walking into a
// crosswalk ahead. It knows the true state of the world (no perception), and its motion is
// kinematically feasible: bounded acceleration and jerk, yaw rate the heading's derivative.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "physics/actors/actor_class.hpp"
#include "physics/actors/path_pose.hpp"
#include "physics/actors/trajectory.hpp"
#include "physics/map/junction_stretch.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/polyline.hpp"
#include "physics/map/polyline_boxes.hpp"
#include "physics/map/segment_frames.hpp"
#include "physics/simulation/bend_envelope.hpp"
#include "physics/simulation/lane_tracker.hpp"
#include "physics/simulation/world_snapshot.hpp"

namespace scenfuzz {

struct FollowerSettings {
  double time_gap = 1.5;             // s, IDM's desired time headway
  double standstill_gap = 2.0;       // m bumper to bumper behind a stopped leader
  double acceleration = 1.5;         // m/s^2, IDM's a (at most the class's maximum)
  double stop_line_gap = 1.0;        // m between the front bumper and a stop line
  double stop_sign_wait = 1.0;       // s standing at a stop sign before going on
  double give_way_time = 4.0;        // s: crossing traffic arriving sooner is given way to
  double crosswalk_clearance = 1.5;  // m around a crosswalk where a pedestrian counts
  double walking_speed = 0.3;        // m/s: a pedestrian at least this fast is walking
  double prediction_time = 1.5;      // s an actor's motion is projected into the path
  double path_margin = 0.3;          // m beside the body that must stay clear
  double min_lookahead = 40;         // m ahead that is watched, at least
  double lookahead_time = 6;         // s of travel ahead that is watched
  // s standing held at a junction's entry by the junction priority rule before it goes on
  // carefully (still stopping for whatever is in its path): breaks a standstill where everyone
  // waits on someone, such as a car parked in the junction.
  double junction_patience = 5;
};

// Why the follower chose its acceleration: tests and the trace's reading.
enum class FollowerReason {
  cruise,
  bend,
  leader,
  red_light,
  stop_sign,
  give_way,
  pedestrian,
  path_end
};

class LaneFollower {
 public:
  // Drives `path` (drawn from `route` by route_path, so that its arc length is the route's
  // distance) from its start at `initial_speed`, aiming for `desired_speed`. At the path's end it
  // stops there, or, when `leaves_at_end`, drives on out of the world (finished()).
  // `places`, route_path's for `path` (empty when not known), say which lane it is on where. The
  // route, path and places are read, not copied (a flow's vehicles share theirs, and a run need
  // not copy kilometres of path for every follower), and must outlive the follower.
  LaneFollower(const RoadMap& map, const LaneRoute& route, const Polyline& path,
               std::span<const PathPlace> places, const ActorClass& body, double desired_speed,
               double initial_speed, bool leaves_at_end, const FollowerSettings& settings = {});

  // Before the first step: puts it `progress` metres along its path instead of at its start, at
  // the same speed, or the most the bends ahead allow (a background-traffic vehicle already on
  // the road at t = 0). Stop lines it has passed are behind it and ignored.
  void start_at(double progress);

  const KinematicState& state() const { return state_; }
  double progress() const { return s_; }  // m along the path
  bool finished() const { return finished_; }
  FollowerReason reason() const { return reason_; }
  // The lane it is on and where along it, from where on its route it is, without asking the map;
  // nullopt where its path leaves the lanes' centre lines (a lane change's sideways move).
  std::optional<LaneFix> lane_fix() const;

  // Chooses the acceleration from the world as it is now (this actor is actor `self` in it) and
  // moves on by dt.
  void step(const WorldSnapshot& world, std::uint32_t self, double dt) {
    decide(world, self, dt);
    move(dt);
  }
  // step's two halves, for a caller that decides for every follower before it moves any (the
  // same world for all): the moves, each a chain of divisions, then overlap in the processor.
  void decide(const WorldSnapshot& world, std::uint32_t self, double dt);
  void move(double dt) {
    if (!finished_) advance(decided_, dt);
  }

 private:
  struct Stop {            // something on the path to stop behind, for now
    double gap = 0;        // m from the front bumper to it
    double clearance = 0;  // m to keep when standing behind it (IDM's s0)
    double speed = 0;      // m/s it moves along the path
    FollowerReason reason = FollowerReason::leader;
    bool predicted = false;  // an actor found where it will be (in_path's second point)
  };
  // The leader followed along the lanes between scans (lane_lead): its gap moves on by how far
  // it moves along the route's lanes less how far this follower moves along its path.
  struct LaneLead {
    std::size_t segment = 0;  // the route segment whose lane it was on at the last step
    double offset = 0;        // its gap at the scan less its route distance ahead of s_ then
  };
  struct Feature {  // a stop line on the route, at path distance `at`
    FeatureAhead feature;
    double at = 0;
    bool served = false;    // stop sign: stood there long enough and the way was clear
    bool occupied = false;  // crosswalk: pedestrians walking in or at it, at the last scan
  };

  void update_facing(const WorldSnapshot& world, std::uint32_t self);
  // Every look interval: the stops ahead (stops_), as they are now.
  void look_ahead(const WorldSnapshot& world, std::uint32_t self, double dt);
  double choose_acceleration(double now);
  double bend_acceleration() const;
  void find_leader(const WorldSnapshot& world, std::uint32_t self, std::vector<Stop>& stops);
  // After a scan found `stop` for the leader: whether it can be followed along the lanes until
  // the next scan (into lane_lead_).
  void start_lane_lead(const WorldSnapshot& world, const Stop& stop);
  // The leader's stop between scans, from its lane position; nullopt when it left the route's
  // lanes (then in_path finds it by geometry).
  std::optional<Stop> lane_lead(const WorldSnapshot& world);
  double lookahead() const {
    return std::max(settings_.min_lookahead, state_.speed * settings_.lookahead_time);
  }
  bool near_path(const WorldSnapshot& world, std::vector<std::uint32_t>& actors) const;
  bool on_lanes_ahead(const WorldSnapshot& world, std::vector<std::uint32_t>& actors);
  // The lanes of the route from route distance `from` to `to` and every lane of the junctions
  // it runs through there, into watched_ (kept while the stretch covers the same route
  // segments).
  void watch_lanes(double from, double to);
  bool behind_in_lane(const WorldSnapshot& world, std::uint32_t k) const;
  std::optional<Stop> in_path(const WorldSnapshot& world, std::uint32_t k);
  // Where in_path looks for an actor: where it is, where it will be, or on its way there.
  enum class Sighting { is, will_be, on_the_way };
  std::optional<Stop> stop_at(const WorldSnapshot& world, std::uint32_t k, MapPoint point,
                              Sighting which, double reach, std::optional<Stop> best);
  bool may_cross(const WorldSnapshot& world, std::uint32_t k, double way) const;
  bool surely_clear_of_path(MapPoint a, MapPoint b, double reach) const;
  PolylineProjection beyond_end(MapPoint point, double reach) const;
  MapPoint predicted_of(const WorldSnapshot& world, std::uint32_t k) const;
  // in_path's first tests, inlined into the scan: whether actor k is surely not in the path
  // (too far off, or behind), which is the answer for most actors at most scans.
  bool surely_not_in_path(const WorldSnapshot& world, std::uint32_t k) const;
  std::size_t first_within(MapPoint point, double reach) const;
  // The same, walking from segment `from` (cheap when the answer is near it).
  std::size_t first_within_from(MapPoint point, double reach, std::size_t from) const;
  bool surely_no_nearer(MapPoint point, double reach, double extent, double gap) const;
  void find_stop_lines(const WorldSnapshot& world, std::uint32_t self, double dt,
                       std::vector<Stop>& stops);
  bool crossing_traffic(const WorldSnapshot& world, std::uint32_t self, const Feature& feature);
  bool pedestrians_at(const WorldSnapshot& world, const Crosswalk& crosswalk) const;
  // The junction priority rule (docs/simulation.md, "Junctions"): a stop at the entry of the
  // junction ahead while it may not enter it.
  void hold_at_junction(const WorldSnapshot& world, std::uint32_t self, std::vector<Stop>& stops);
  bool box_blocked(const std::vector<Stop>& stops, const JunctionStretch& stretch,
                   double front) const;
  bool gives_way_in_junction(const WorldSnapshot& world, std::uint32_t self,
                             const JunctionStretch& stretch);
  // The junction lane a stop line at `feature` leads into (the feature's own lane if it is one).
  std::optional<LaneIndex> junction_lane_after(const FeatureAhead& feature) const;
  // Whether conflicting lane `other` meets `mine` at all (RoadMap::junction_conflict_points):
  // two roundabout entries share the ring as successor but never meet.
  bool meets(LaneIndex mine, LaneIndex other) const;
  // Whether a vehicle of `length` at `s` on conflicting lane `other`, at `speed`, has the way
  // over `mine`: on a lane that meets it, and on a roundabout's ring (a lane running round into
  // itself) only while it is within the give-way time of where `mine` joins it.
  bool meets_soon(LaneIndex mine, LaneIndex other, double s, double length, double speed) const;
  void advance(double acceleration, double dt);
  // Extends boxes_, frames_ and envelope_ over what this step can read (prepare_further), when
  // they do not cover it yet.
  void prepare_ahead() {
    if (s_ + lookahead() > prepared_until_ || segment_ + 1 >= envelope_.final_count() ||
        state_.speed > envelope_.speed_bound())
      prepare_further();
  }
  void prepare_further();
  // The headings of segment_ - 1 to a run beyond segment_ + 1, into headings_ (headed_until_).
  void make_headings_known();

  const RoadMap* map_;
  const LaneRoute* route_;
  const Polyline* path_;
  std::span<const PathPlace> places_;  // of path_'s points (lane_fix), or none
  LazyHeadings headings_;              // of each path segment, computed where needed
  PolylineBoxes boxes_;                // of runs of path segments, for nearest_on_path
  SegmentFrames frames_;               // of path segments, for nearest_on_path's projections
  std::vector<double> route_starts_;   // route distance where each route segment begins
  std::vector<LaneIndex> watched_;     // on_lanes_ahead's lanes, ascending
  std::size_t watched_first_ = 1, watched_last_ = 0;  // the route segments they are of
  BendEnvelope envelope_;       // at each vertex: the most speed from which the bends ahead can be
                                // taken at comfortable deceleration
  double prepared_until_ = -1;  // m of path over which boxes_ and frames_ are made
  std::vector<Feature> features_;
  std::size_t next_feature_ = 0;           // the first not yet passed
  std::vector<Stop> stops_;                // found at the last look
  std::vector<std::uint32_t> candidates_;  // the actors a scan looks at (near_path)
  // For actor k, hints_[2k] (where it is) and hints_[2k + 1] (where it will be): 1 + the path
  // segment nearest to that point when in_path last looked, or 0. A search seeded with a nearby
  // segment's distance skips most boxes (nearest_on_path's `known`); its answer is the same.
  std::vector<std::uint32_t> hints_;
  std::vector<std::uint32_t> starts_;  // the same slots: 1 + first_within's answer then, or 0
  double next_look_ = 0;               // s: when look_ahead looks again
  double looked_at_ = 0;               // s: when it last looked
  double looked_from_ = 0;             // m: s_ then
  double next_scan_ = 0;               // s: when every actor is looked at again
  bool scanning_ = false;              // this step is a scan
  std::int64_t leader_ = -1;           // the actor followed between scans, or -1
  std::optional<LaneLead> lane_lead_;  // how, when it is followed along the lanes
  ActorClass body_;
  double desired_speed_ = 0;
  bool leaves_at_end_ = false;
  FollowerSettings settings_;
  double root_ab_ =
      0;  // sqrt(a b) of IDM's braking term, of a and b as choose_acceleration takes them

  KinematicState state_;
  double s_ = 0;
  std::size_t segment_ = 0;  // path_->segment_at(s_), kept as s_ moves on (segment_walk.hpp)
  // The headings of the path segments from segment_ - 1 up to (not including) this one are
  // known, and the blends of the vertices from segment_ up to it: advance computes them a run
  // ahead at a time, so that most steps only compare.
  std::size_t headed_until_ = 0;
  std::vector<VertexBlend> blends_;  // by vertex (path_pose.hpp), where known
  // cos and sin of state_.heading (update_facing, at each look); NaN: not taken yet.
  MapPoint facing_{1, 0};
  double facing_heading_ = std::numeric_limits<double>::quiet_NaN();  // whose they are
  double applied_ = 0;  // m/s^2 asked of the vehicle at the last step, for the jerk limit
  double decided_ = 0;  // m/s^2 chosen by decide, for move
  bool finished_ = false;
  FollowerReason reason_ = FollowerReason::cruise;
  double stopped_since_ = -1;   // s: when it came to stand at the stop sign it waits at
  double held_since_ = -1;      // s: when it came to stand held at a junction's entry
  double released_entry_ = -1;  // route distance of the entry its patience let it through
  bool gives_way_ = false;      // gives_way_in_junction at the last scan
  // The junction stretch ahead of the front bumper, found again only once the front has passed
  // its exit (the front never moves back, so until then it is still the first ahead).
  std::optional<JunctionStretch> stretch_;
  bool stretch_known_ = false;
};

}  // namespace scenfuzz
