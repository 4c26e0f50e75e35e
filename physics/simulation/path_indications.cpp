// The lane changes and junction turns along a drawn path (path_indications.hpp).
#include "physics/simulation/path_indications.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "physics/map/lane_queries.hpp"
#include "physics/simulation/lane_tracker.hpp"

namespace scenfuzz {
namespace {

constexpr double kSpacing = 1;  // m between the path points looked at
// m sideways per m along: a slower drift is no part of a lane change. A smoothstep move of a lane
// width over 30 m (waypoint_path's) is slower only within about a metre of its ends.
constexpr double kSideways = 0.02;

constexpr double kHalfTurn = std::numbers::pi / 2;

struct PathSample {
  double s = 0;
  MapPose pose;                   // on the path
  std::optional<LaneIndex> lane;  // the lane the point lies inside (LaneTracker's)
  double lane_s = 0;              // where along it
};

// The path every kSpacing metres, with the lane under each point. The lane is tracked as the
// simulation tracks an actor's (cheap while the path stays on one lane; where lanes overlap, the
// one heading most nearly the path's way when the path comes onto them).
std::vector<PathSample> sample_path(const RoadMap& map, const Polyline& path,
                                    double widest_half_lane) {
  LaneTracker tracker(widest_half_lane);
  std::vector<PathSample> samples;
  const auto steps = static_cast<std::size_t>(std::ceil(path.length() / kSpacing));
  samples.reserve(steps + 1);
  const std::vector<MapPoint>& points = path.points();
  const std::vector<double>& at = path.arc_lengths();
  std::size_t segment = 0;  // the path's segment the sample lies on: walked, not searched for
  for (std::size_t i = 0; i <= steps; ++i) {
    PathSample sample;
    sample.s = std::min(path.length(), static_cast<double>(i) * kSpacing);
    while (segment + 2 < points.size() && at[segment + 1] <= sample.s) ++segment;
    const MapPoint& a = points[segment];
    const MapPoint& b = points[segment + 1];
    const double t = (sample.s - at[segment]) / (at[segment + 1] - at[segment]);
    sample.pose = {{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)},
                   std::atan2(b.y - a.y, b.x - a.x)};
    const LaneFix fix = tracker.update(map, sample.pose.position, sample.pose.heading);
    if (fix.lane >= 0) {
      sample.lane = static_cast<LaneIndex>(fix.lane);
      sample.lane_s = fix.s;
    }
    samples.push_back(sample);
  }
  return samples;
}

// The sample's offset from its lane's centre line, left positive (looked at near lane changes
// only).
double lateral_of(const RoadMap& map, const PathSample& sample) {
  const auto centre = lane_pose_at(map, *sample.lane, sample.lane_s);
  if (!centre) return 0;
  const double dx = sample.pose.position.x - centre->position.x;
  const double dy = sample.pose.position.y - centre->position.y;
  return -dx * std::sin(centre->heading) + dy * std::cos(centre->heading);
}

// Whether the sample's lane runs against the path (the oncoming lane).
bool against(const RoadMap& map, const PathSample& sample) {
  return std::abs(angle_difference(lane_heading_at(map, *sample.lane, sample.lane_s),
                                   sample.pose.heading)) > kHalfTurn;
}

bool holds(const std::vector<LaneIndex>& lanes, LaneIndex lane) {
  return std::find(lanes.begin(), lanes.end(), lane) != lanes.end();
}

bool is_neighbour(const Lane& lane, LaneIndex other) {
  return holds(lane.left_forward_neighbours, other) ||
         holds(lane.right_forward_neighbours, other) ||
         holds(lane.left_reverse_neighbours, other) || holds(lane.right_reverse_neighbours, other);
}

// The lane a move from `from` into `to` crosses sideways from: `from` when `to` is its
// neighbour, else a lane following it whose neighbour `to` is (the line crossed where `from`
// ends); nullopt for no sideways move (a successor, a lane far off).
std::optional<LaneIndex> crossed_from(const RoadMap& map, LaneIndex from, LaneIndex to) {
  if (is_neighbour(map.lane(from), to)) return from;
  for (const LaneIndex next : map.lane(from).successors)
    if (is_neighbour(map.lane(next), to)) return next;
  return std::nullopt;
}

// Whether the path moves sideways by `toward` (+1 left, -1 right) from sample k to k + 1, both on
// a lane that the lateral offsets are comparable on (one lane, or one and its successor).
bool moves_sideways(const RoadMap& map, const std::vector<PathSample>& samples, std::size_t k,
                    double toward) {
  const PathSample& a = samples[k];
  const PathSample& b = samples[k + 1];
  if (!a.lane || !b.lane) return false;
  if (*a.lane != *b.lane && !holds(map.lane(*a.lane).successors, *b.lane)) return false;
  return toward * (lateral_of(map, b) - lateral_of(map, a)) > kSideways * (b.s - a.s);
}

// The lane changes: each crossing into a neighbour, stretched back and on while the path moves
// sideways its way (not back past the crossing before it).
std::vector<IndicationStretch> lane_changes(const RoadMap& map,
                                            const std::vector<PathSample>& samples) {
  std::vector<IndicationStretch> changes;
  std::size_t floor = 0;            // the sample after the last crossing
  std::optional<std::size_t> last;  // the last sample on a lane
  for (std::size_t c = 0; c < samples.size(); ++c) {
    if (!samples[c].lane) continue;
    if (!last || *samples[*last].lane == *samples[c].lane) {
      last = c;
      continue;
    }
    const std::size_t previous = *last;
    const LaneIndex after = *samples[c].lane;
    last = c;
    const auto from = crossed_from(map, *samples[previous].lane, after);
    if (!from) continue;
    const Lane& crossed = map.lane(*from);
    // Sideways as the lanes run (the laterals' frames): towards `after`, and on it away from
    // `from`, which is the other way on a lane running the other way.
    const bool left = holds(crossed.left_forward_neighbours, after) ||
                      holds(crossed.left_reverse_neighbours, after);
    const bool reverse = holds(crossed.left_reverse_neighbours, after) ||
                         holds(crossed.right_reverse_neighbours, after);
    const double toward = left ? 1.0 : -1.0;
    std::size_t begin = previous;
    while (begin > floor && moves_sideways(map, samples, begin - 1, toward)) --begin;
    std::size_t end = c;
    while (end + 1 < samples.size() &&
           moves_sideways(map, samples, end, reverse ? -toward : toward))
      ++end;
    // The driver's left is the lane's unless it drives against the lane (back from the oncoming
    // lane after passing).
    const bool drivers_left = left != against(map, samples[previous]);
    changes.push_back(
        {samples[begin].s, samples[end].s,
         drivers_left ? vehicle_signal::left_indicator : vehicle_signal::right_indicator});
    floor = c;
  }
  return changes;
}

// The lane seen at the most samples among [first, last] (on a lane each).
LaneIndex most_seen(const std::vector<PathSample>& samples, std::size_t first, std::size_t last) {
  std::vector<std::pair<LaneIndex, std::size_t>> counts;
  for (std::size_t k = first; k <= last; ++k) {
    if (!samples[k].lane) continue;
    auto it = std::find_if(counts.begin(), counts.end(),
                           [&](const auto& count) { return count.first == *samples[k].lane; });
    if (it == counts.end())
      counts.emplace_back(*samples[k].lane, 1);
    else
      ++it->second;
  }
  return std::max_element(counts.begin(), counts.end(),
                          [](const auto& a, const auto& b) { return a.second < b.second; })
      ->first;
}

std::optional<std::uint32_t> junction_of(const RoadMap& map, const PathSample& sample) {
  if (!sample.lane) return std::nullopt;
  return map.lane(*sample.lane).junction;
}

// Round a roundabout (the run [first, last] has samples on a ring, and on a lane after it): the
// exit's indicator only, from where the exit lane begins, with no least notice, as a lane route
// does (route_indications.cpp). The exit lane's start is its lane s back from the first sample on
// it: the tracker keeps to the ring a few metres past the split, where the two overlap.
std::optional<IndicationStretch> roundabout_exit(const RoadMap& map,
                                                 const std::vector<PathSample>& samples,
                                                 std::size_t first, std::size_t last, double exit) {
  std::optional<std::size_t> ring;
  for (std::size_t k = first; k <= last; ++k)
    if (samples[k].lane && runs_into_itself(map, *samples[k].lane)) ring = k;
  if (!ring) return std::nullopt;
  for (std::size_t k = *ring + 1; k <= last; ++k) {
    if (!samples[k].lane || *samples[k].lane == *samples[*ring].lane) continue;
    const double begin = std::max(samples[first].s, samples[k].s - samples[k].lane_s);
    return IndicationStretch{begin, exit, junction_lane_indicator(map, *samples[k].lane), 0};
  }
  return std::nullopt;
}

// The junction turns: runs of samples on one junction's lanes (points on no lane do not end
// one), from halfway between the last point before and the first in, to halfway out.
std::vector<IndicationStretch> junction_turns(const RoadMap& map,
                                              const std::vector<PathSample>& samples) {
  std::vector<IndicationStretch> turns;
  for (std::size_t first = 0; first < samples.size(); ++first) {
    const auto junction = junction_of(map, samples[first]);
    if (!junction) continue;
    std::size_t last = first;
    for (std::size_t k = first + 1; k < samples.size(); ++k) {
      if (!samples[k].lane) continue;
      if (junction_of(map, samples[k]) != junction) break;
      last = k;
    }
    const double entry = first > 0 ? (samples[first - 1].s + samples[first].s) / 2 : 0;
    const double exit =
        last + 1 < samples.size() ? (samples[last].s + samples[last + 1].s) / 2 : samples[last].s;
    if (auto round = roundabout_exit(map, samples, first, last, exit)) {
      if (round->indicator != 0) turns.push_back(*round);
      first = last;
      continue;
    }
    const VehicleSignals indicator = junction_lane_indicator(map, most_seen(samples, first, last));
    if (indicator != 0) turns.push_back({entry, exit, indicator, kTurnNotice});
    first = last;
  }
  return turns;
}

}  // namespace

std::vector<IndicationStretch> path_indications(const RoadMap& map, const Polyline& path,
                                                double widest_half_lane) {
  if (path.points().size() < 2 || path.length() <= 0) return {};
  const std::vector<PathSample> samples = sample_path(map, path, widest_half_lane);
  std::vector<IndicationStretch> stretches = lane_changes(map, samples);
  for (const IndicationStretch& turn : junction_turns(map, samples)) stretches.push_back(turn);
  std::sort(
      stretches.begin(), stretches.end(),
      [](const IndicationStretch& a, const IndicationStretch& b) { return a.begin < b.begin; });
  return stretches;
}

}  // namespace scenfuzz
