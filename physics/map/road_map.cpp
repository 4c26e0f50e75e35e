// build_road_map: checks a MapDescription, resolves its ids to indices and indexes its lanes.
#include "physics/map/road_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "physics/map/junction_conflicts.hpp"
#include "physics/map/lane_segment_index.hpp"

namespace scenfuzz {

void MapBounds::include(MapPoint p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
  min.x = std::min(min.x, p.x);
  min.y = std::min(min.y, p.y);
  max.x = std::max(max.x, p.x);
  max.y = std::max(max.y, p.y);
}

RoadMap::RoadMap() = default;
RoadMap::RoadMap(RoadMap&&) noexcept = default;
RoadMap& RoadMap::operator=(RoadMap&&) noexcept = default;
RoadMap::~RoadMap() = default;

std::optional<LaneIndex> RoadMap::find_lane(std::string_view id) const {
  auto found = lane_by_id_.find(std::string(id));
  if (found == lane_by_id_.end()) return std::nullopt;
  return found->second;
}

std::optional<LaneStation> RoadMap::find_lane_station(std::string_view id, double s) const {
  if (const std::optional<LaneIndex> lane = find_lane(id)) return LaneStation{*lane, s};
  const auto chain = chains_.find(std::string(id));
  if (chain == chains_.end() || chain->second.empty()) return std::nullopt;
  const std::vector<ChainPiece>& pieces = chain->second;
  std::size_t piece = 0;
  while (piece + 1 < pieces.size() && pieces[piece + 1].start <= s) ++piece;
  return LaneStation{pieces[piece].lane, s - pieces[piece].start};
}

std::size_t RoadMap::stop_sign_count() const {
  return static_cast<std::size_t>(std::count_if(
      signs_.begin(), signs_.end(), [](const Sign& sign) { return sign.kind == SignKind::stop; }));
}

std::size_t RoadMap::yield_sign_count() const { return signs_.size() - stop_sign_count(); }

namespace {

double narrowest_width(const std::vector<WidthSample>& samples) {
  double narrowest = std::numeric_limits<double>::infinity();
  for (const WidthSample& sample : samples) narrowest = std::min(narrowest, sample.width);
  return narrowest;
}

// Widths from samples as given: sorted by s, finite, non-negative.
std::vector<WidthSample> clean_width_samples(std::vector<WidthSample> samples) {
  std::erase_if(samples, [](const WidthSample& sample) {
    return !std::isfinite(sample.s) || !std::isfinite(sample.width) || sample.width < 0;
  });
  std::stable_sort(samples.begin(), samples.end(),
                   [](const WidthSample& a, const WidthSample& b) { return a.s < b.s; });
  return samples;
}

// Widths measured from a drawn boundary: the distance to it from each centre-line vertex.
std::vector<WidthSample> widths_from_boundary(const Polyline& centre_line,
                                              const std::vector<MapPoint>& boundary) {
  std::vector<WidthSample> samples;
  if (boundary.size() < 2) return samples;
  Polyline boundary_line;
  try {
    boundary_line = Polyline(boundary);
  } catch (const std::invalid_argument&) {
    return samples;
  }
  for (std::size_t i = 0; i < centre_line.points().size(); ++i) {
    samples.push_back(
        {centre_line.arc_lengths()[i], boundary_line.project(centre_line.points()[i]).distance});
  }
  return samples;
}

}  // namespace

double width_at(const std::vector<WidthSample>& samples, double s) {
  if (samples.size() == 1 || s <= samples.front().s) return samples.front().width;
  if (s >= samples.back().s) return samples.back().width;
  auto after =
      std::upper_bound(samples.begin(), samples.end(), s,
                       [](double value, const WidthSample& sample) { return value < sample.s; });
  const WidthSample& b = *after;
  const WidthSample& a = *(after - 1);
  if (b.s - a.s <= 0) return b.width;
  return a.width + (s - a.s) / (b.s - a.s) * (b.width - a.width);
}

namespace {

// A boundary drawn at `side` (+1 left, -1 right) times the width from each centre-line vertex.
std::vector<MapPoint> offset_boundary(const Polyline& centre_line,
                                      const std::vector<WidthSample>& widths, double side) {
  std::vector<MapPoint> boundary;
  const auto& points = centre_line.points();
  for (std::size_t i = 0; i < points.size(); ++i) {
    double s = centre_line.arc_lengths()[i];
    // At a vertex, the normal of the bisector keeps the boundary parallel around bends.
    double heading_in = centre_line.heading_at(i == 0 ? 0 : centre_line.arc_lengths()[i - 1]);
    double heading_out = centre_line.heading_at(s);
    double heading = heading_in + angle_difference(heading_out, heading_in) / 2;
    double offset = side * width_at(widths, s);
    boundary.push_back(
        {points[i].x - std::sin(heading) * offset, points[i].y + std::cos(heading) * offset});
  }
  return boundary;
}

bool contains(const std::vector<LaneIndex>& lanes, LaneIndex lane) {
  return std::find(lanes.begin(), lanes.end(), lane) != lanes.end();
}

class MapBuilder {
 public:
  explicit MapBuilder(RoadMap& map) : map_(map) {}

  std::vector<LaneIndex> resolve_lanes(const std::string& owner, const char* relation,
                                       const std::vector<std::string>& ids) {
    std::vector<LaneIndex> lanes;
    for (const std::string& id : ids) {
      auto lane = map_.find_lane(id);
      if (!lane) {
        warn(owner + ": " + relation + " '" + id + "' is not a lane of the map");
      } else if (!contains(lanes, *lane)) {
        lanes.push_back(*lane);
      }
    }
    return lanes;
  }

  std::vector<LaneCrossing> resolve_crossings(const std::string& owner,
                                              const std::vector<LaneCrossingDescription>& given) {
    std::vector<LaneCrossing> crossings;
    for (const LaneCrossingDescription& crossing : given) {
      auto lane = map_.find_lane(crossing.lane);
      if (!lane) {
        warn(owner + ": crosses '" + crossing.lane + "', which is not a lane of the map");
        continue;
      }
      if (!std::isfinite(crossing.s_begin) || !std::isfinite(crossing.s_end)) {
        warn(owner + ": its crossing of '" + crossing.lane + "' is not a finite interval");
        continue;
      }
      double length = map_.lane(*lane).length();
      double s_begin = std::clamp(std::min(crossing.s_begin, crossing.s_end), 0.0, length);
      double s_end = std::clamp(std::max(crossing.s_begin, crossing.s_end), 0.0, length);
      crossings.push_back({*lane, s_begin, s_end});
    }
    return crossings;
  }

  void warn(std::string message) { warnings_.push_back(std::move(message)); }
  std::vector<std::string> take_warnings() { return std::move(warnings_); }

 private:
  RoadMap& map_;
  std::vector<std::string> warnings_;
};

}  // namespace

RoadMap build_road_map(MapDescription description) {
  RoadMap map;
  map.name_ = std::move(description.name);
  map.source_ = std::move(description.source);
  map.projection_ = std::move(description.projection);
  const std::string& source = map.source_.empty() ? map.name_ : map.source_;
  if (description.lanes.empty()) throw MapError(source + ": error: the map has no lanes");
  double half_default_width = description.default_lane_width / 2;
  if (!(half_default_width > 0)) half_default_width = 1.75;

  map.lanes_.reserve(description.lanes.size());
  for (LaneDescription& given : description.lanes) {
    if (given.id.empty()) throw MapError(source + ": error: a lane has no id");
    LaneIndex index = static_cast<LaneIndex>(map.lanes_.size());
    if (!map.lane_by_id_.emplace(given.id, index).second)
      throw MapError(source + ": error: two lanes have the id '" + given.id + "'");
    Lane lane;
    lane.id = given.id;
    try {
      lane.centre_line = Polyline(given.centre_line);
    } catch (const std::invalid_argument& error) {
      throw MapError(source + ": error: lane '" + given.id +
                     "': its centre line needs at least two distinct, finite points (" +
                     error.what() + ")");
    }
    lane.left_width = clean_width_samples(std::move(given.left_width));
    if (lane.left_width.empty())
      lane.left_width = widths_from_boundary(lane.centre_line, given.left_boundary);
    if (lane.left_width.empty()) lane.left_width = {{0, half_default_width}};
    lane.right_width = clean_width_samples(std::move(given.right_width));
    if (lane.right_width.empty())
      lane.right_width = widths_from_boundary(lane.centre_line, given.right_boundary);
    if (lane.right_width.empty()) lane.right_width = {{0, half_default_width}};
    lane.left_boundary = given.left_boundary.size() >= 2
                             ? std::move(given.left_boundary)
                             : offset_boundary(lane.centre_line, lane.left_width, +1);
    lane.right_boundary = given.right_boundary.size() >= 2
                              ? std::move(given.right_boundary)
                              : offset_boundary(lane.centre_line, lane.right_width, -1);
    lane.left_boundary_type = given.left_boundary_type;
    lane.right_boundary_type = given.right_boundary_type;
    lane.speed_limit =
        std::isfinite(given.speed_limit) && given.speed_limit > 0 ? given.speed_limit : 0;
    lane.turn = given.turn;
    map.lanes_.push_back(std::move(lane));
  }

  MapBuilder builder(map);
  std::unordered_map<std::string, std::uint32_t> junction_by_id;
  for (JunctionDescription& given : description.junctions) {
    junction_by_id.emplace(given.id, static_cast<std::uint32_t>(map.junctions_.size()));
    map.junctions_.push_back({std::move(given.id), std::move(given.outline), {}});
  }

  for (std::size_t i = 0; i < description.lanes.size(); ++i) {
    const LaneDescription& given = description.lanes[i];
    Lane& lane = map.lanes_[i];
    std::string owner = "lane '" + given.id + "'";
    lane.successors = builder.resolve_lanes(owner, "successor", given.successors);
    lane.predecessors = builder.resolve_lanes(owner, "predecessor", given.predecessors);
    lane.left_forward_neighbours =
        builder.resolve_lanes(owner, "left neighbour", given.left_forward_neighbours);
    lane.right_forward_neighbours =
        builder.resolve_lanes(owner, "right neighbour", given.right_forward_neighbours);
    lane.left_reverse_neighbours =
        builder.resolve_lanes(owner, "left reverse neighbour", given.left_reverse_neighbours);
    lane.right_reverse_neighbours =
        builder.resolve_lanes(owner, "right reverse neighbour", given.right_reverse_neighbours);
    if (!given.junction.empty()) {
      auto junction = junction_by_id.find(given.junction);
      if (junction == junction_by_id.end())
        builder.warn(owner + ": junction '" + given.junction + "' is not in the map");
      else
        lane.junction = junction->second;
    }
  }
  // Successor and predecessor links are two views of one relation: make them agree.
  for (LaneIndex from = 0; from < map.lanes_.size(); ++from) {
    for (LaneIndex to : map.lanes_[from].successors)
      if (!contains(map.lanes_[to].predecessors, from)) map.lanes_[to].predecessors.push_back(from);
    for (LaneIndex to : map.lanes_[from].predecessors)
      if (!contains(map.lanes_[to].successors, from)) map.lanes_[to].successors.push_back(from);
  }

  for (const LaneChainDescription& given : description.lane_chains) {
    std::vector<RoadMap::ChainPiece> pieces;
    for (const LaneChainPiece& piece : given.pieces)
      if (const std::optional<LaneIndex> lane = map.find_lane(piece.lane))
        pieces.push_back({*lane, piece.start});
      else
        builder.warn("lane chain '" + given.id + "': lane '" + piece.lane + "' is not in the map");
    map.chains_.emplace(given.id, std::move(pieces));
  }

  for (TrafficLightDescription& given : description.traffic_lights) {
    TrafficLight light;
    light.lanes = builder.resolve_crossings("traffic light '" + given.id + "'", given.lanes);
    light.id = std::move(given.id);
    light.heads = std::move(given.heads);
    light.stop_lines = std::move(given.stop_lines);
    light.plan = std::move(given.plan);
    map.traffic_lights_.push_back(std::move(light));
  }
  for (SignDescription& given : description.signs) {
    Sign sign;
    sign.lanes = builder.resolve_crossings("sign '" + given.id + "'", given.lanes);
    sign.id = std::move(given.id);
    sign.kind = given.kind;
    sign.stop_lines = std::move(given.stop_lines);
    map.signs_.push_back(std::move(sign));
  }
  for (CrosswalkDescription& given : description.crosswalks) {
    Crosswalk crosswalk;
    crosswalk.lanes = builder.resolve_crossings("crosswalk '" + given.id + "'", given.lanes);
    crosswalk.id = std::move(given.id);
    crosswalk.outline = std::move(given.outline);
    crosswalk.walk_plan = std::move(given.walk_plan);
    map.crosswalks_.push_back(std::move(crosswalk));
  }

  auto attach = [&map](FeatureKind kind, std::size_t index,
                       const std::vector<LaneCrossing>& crossings) {
    for (const LaneCrossing& crossing : crossings)
      map.lanes_[crossing.lane].features.push_back(
          {kind, static_cast<std::uint32_t>(index), crossing.s_begin, crossing.s_end});
  };
  for (std::size_t i = 0; i < map.traffic_lights_.size(); ++i)
    attach(FeatureKind::traffic_light, i, map.traffic_lights_[i].lanes);
  for (std::size_t i = 0; i < map.signs_.size(); ++i)
    attach(map.signs_[i].kind == SignKind::stop ? FeatureKind::stop_sign : FeatureKind::yield_sign,
           i, map.signs_[i].lanes);
  for (std::size_t i = 0; i < map.crosswalks_.size(); ++i)
    attach(FeatureKind::crosswalk, i, map.crosswalks_[i].lanes);
  for (Lane& lane : map.lanes_) {
    std::stable_sort(
        lane.features.begin(), lane.features.end(),
        [](const LaneFeature& a, const LaneFeature& b) { return a.s_begin < b.s_begin; });
  }

  for (const Lane& lane : map.lanes_) {
    for (MapPoint point : lane.left_boundary) map.bounds_.include(point);
    for (MapPoint point : lane.right_boundary) map.bounds_.include(point);
    for (MapPoint point : lane.centre_line.points()) map.bounds_.include(point);
  }
  for (const Junction& junction : map.junctions_)
    for (MapPoint point : junction.outline) map.bounds_.include(point);
  for (const Crosswalk& crosswalk : map.crosswalks_)
    for (MapPoint point : crosswalk.outline) map.bounds_.include(point);

  map.segment_index_ = std::make_unique<LaneSegmentIndex>(map.lanes_);
  // Tables derived from the lanes, for every simulation on the map.
  for (Lane& lane : map.lanes_) {
    lane.narrowest_left_width = narrowest_width(lane.left_width);
    lane.narrowest_right_width = narrowest_width(lane.right_width);
    for (const auto* side : {&lane.left_width, &lane.right_width})
      for (const WidthSample& sample : *side)
        map.widest_half_lane_ = std::max(map.widest_half_lane_, sample.width);
  }
  for (LaneIndex lane = 0; lane < map.lanes_.size(); ++lane)
    if (auto junction = map.lanes_[lane].junction; junction && *junction < map.junctions_.size())
      map.junctions_[*junction].lanes.push_back(lane);
  map.conflicts_ = std::make_unique<JunctionConflicts>(map.lanes_.size());
  map.warnings_ = builder.take_warnings();
  return map;
}

const std::vector<LaneIndex>& RoadMap::junction_conflicts(LaneIndex lane) const {
  return conflicts_->of(*this, lane);
}

const std::vector<ConflictPoint>& RoadMap::junction_conflict_points(LaneIndex lane) const {
  return conflicts_->points_of(*this, lane);
}

}  // namespace scenfuzz
