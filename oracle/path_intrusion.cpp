// The intrusion from a scan back from the collision over the samples where the intruder was in
// the vehicle's path, the intruder's standstill and the pair geometry at the moment that counts.
// The path of a vehicle following its lane is the whole lane ahead, not the band its body sweeps:
// a driver may use all of its lane, and a body standing over the lane's edge stands in its way.
#include "oracle/path_intrusion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

#include "oracle/pair_geometry.hpp"
#include "oracle/right_of_way.hpp"
#include "oracle/rss_distances.hpp"
#include "oracle/rss_response.hpp"
#include "physics/map/lane_queries.hpp"

namespace scenfuzz {

namespace {

constexpr double kSideImpactLookBack = 0.5;            // s, as path_entry
constexpr double kFollowsLane = std::numbers::pi / 4;  // as pair_geometry

// Half the across-frame extent of a box turned by `a` against the frame (a radius for a round
// body).
double across_extent(const TraceActor& actor, double a) {
  if (actor.shape != BodyShape::box) return actor.length / 2;
  return actor.length / 2 * std::abs(std::sin(a)) + actor.width / 2 * std::abs(std::cos(a));
}

// Whether `intruder`'s body overlaps the lane `vehicle` follows at `i`, ahead of its centre;
// nullopt when the vehicle follows no lane there.
std::optional<bool> in_lane_ahead(const Trace& trace, const RoadMap& map, ActorId vehicle,
                                  ActorId intruder, std::size_t i, const PairGeometry& g) {
  const TraceActor& v = trace.actors[vehicle];
  if (v.lane[i] < 0) return std::nullopt;
  const auto lane = static_cast<LaneIndex>(v.lane[i]);
  const double s = std::clamp(v.s[i], 0.0, map.lane(lane).length());
  const std::optional<MapPose> centre = lane_pose_at(map, lane, s);
  if (!centre || std::abs(wrap_angle(v.heading[i] - centre->heading)) > kFollowsLane)
    return std::nullopt;
  const double h = g.frame_heading;
  const double own_offset =
      -(v.x[i] - centre->position.x) * std::sin(h) + (v.y[i] - centre->position.y) * std::cos(h);
  const double offset = own_offset + g.dy;  // the intruder's centre from the lane's centre line
  const double extent = across_extent(trace.actors[intruder], g.heading_difference);
  return g.dx > 0 && offset - extent < lane_left_width_at(map, lane, s) &&
         offset + extent > -lane_right_width_at(map, lane, s);
}

bool in_path(const Trace& trace, const RoadMap& map, ActorId vehicle, ActorId intruder,
             std::size_t i) {
  const PairGeometry g = pair_geometry(trace, map, vehicle, intruder, i);
  return in_lane_ahead(trace, map, vehicle, intruder, i, g).value_or(g.gap_lat < 0 && g.dx > 0);
}

// Whether `intruder` kept to its own lane, along it, while `vehicle` drove in that lane against
// its direction (out on the oncoming lane to overtake, or the wrong way): then the vehicle brought
// its path to the intruder, which was where it belonged. Not in a junction, where lanes overlap.
bool kept_to_lane_met_against(const Trace& trace, const RoadMap& map, ActorId vehicle,
                              ActorId intruder, std::size_t i) {
  const TraceActor& in = trace.actors[intruder];
  if (in.lane[i] < 0) return false;
  const auto lane = static_cast<LaneIndex>(in.lane[i]);
  if (map.lane(lane).junction) return false;
  const std::optional<MapPose> centre =
      lane_pose_at(map, lane, std::clamp(in.s[i], 0.0, map.lane(lane).length()));
  if (!centre || std::abs(wrap_angle(in.heading[i] - centre->heading)) > kFollowsLane) return false;
  const TraceActor& v = trace.actors[vehicle];
  const std::optional<LaneProjection> on =
      project_onto_lanes(map, {v.x[i], v.y[i]}, std::span<const LaneIndex>(&lane, 1));
  return on && on->inside &&
         std::abs(wrap_angle(v.heading[i] - centre->heading + std::numbers::pi)) < kFollowsLane;
}

// The first sample of the standstill that lasts up to `last`; nullopt when moving at `last`.
std::optional<std::size_t> rest_since(const TraceActor& actor, std::size_t last) {
  if (actor.speed[last] > kStandstillSpeed) return std::nullopt;
  std::size_t i = last;
  while (i > actor.present_from && actor.speed[i - 1] <= kStandstillSpeed) --i;
  return i;
}

// The first sample of the stretch in the path that lasts to the collision (or to at most the
// look-back before it: a side impact); nullopt when not in the path then.
std::optional<std::size_t> entered(const Trace& trace, const RoadMap& map, ActorId vehicle,
                                   ActorId intruder, std::size_t k, std::size_t first) {
  const auto look_back = static_cast<std::size_t>(std::ceil(kSideImpactLookBack / trace.dt));
  std::optional<std::size_t> last;
  for (std::size_t i = k + 1; i-- > first && k - i <= look_back;)
    if (in_path(trace, map, vehicle, intruder, i)) {
      last = i;
      break;
    }
  if (!last) return std::nullopt;
  std::size_t entry = *last;
  while (entry > first && in_path(trace, map, vehicle, intruder, entry - 1)) --entry;
  return entry;
}

}  // namespace

std::optional<PathIntrusion> path_intrusion(const Trace& trace, const RoadMap& map, ActorId vehicle,
                                            ActorId intruder, std::size_t collision_sample,
                                            const RssParameters& rss) {
  const std::size_t first =
      std::max(trace.actors[vehicle].present_from, trace.actors[intruder].present_from);
  const std::optional<std::size_t> entry =
      entered(trace, map, vehicle, intruder, collision_sample, first);
  if (!entry || *entry == first) return std::nullopt;
  if (kept_to_lane_met_against(trace, map, vehicle, intruder, *entry)) return std::nullopt;
  const std::optional<std::size_t> rest = rest_since(trace.actors[intruder], collision_sample);
  if (rest && *rest < *entry) return std::nullopt;  // it stood; the path came to it
  PathIntrusion found;
  // Coming to rest only at the impact is not standing in the way: it was still moving in.
  found.came_to_rest = rest && *rest > *entry && *rest < collision_sample;
  found.sample = found.came_to_rest ? *rest : *entry;
  const PairGeometry g = pair_geometry(trace, map, vehicle, intruder, found.sample);
  found.gap = std::max(0.0, g.gap_lon);
  found.speed = std::max(0.0, g.reference_lon);
  found.safe_distance = rss_safe_longitudinal_same(found.speed, std::max(0.0, g.other_lon),
                                                   rss_response_time(vehicle, rss), rss);
  return found;
}

}  // namespace scenfuzz
