// The actors by the lanes they occupy, one step at a time (see lane_occupancy.hpp).
#include "physics/simulation/lane_occupancy.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "physics/map/polygon.hpp"
#include "physics/map/segment_walk.hpp"
#include "physics/simulation/predicted_points.hpp"

namespace scenfuzz {
namespace {

// m along the lanes beyond the body's reach that still files it on the next lane: a follower's
// search finds a point within its reach of the path, a few metres either way.
constexpr double kAlongMargin = 2;
// Successor and predecessor links followed from an actor's lane: far more than a body and 1.5 s
// of driving cross, and a bound for rings (a closed lane is its own successor).
constexpr int kMaxDepth = 6;

}  // namespace

LaneOccupancy::LaneOccupancy(const RoadMap& map) : map_(&map) {
  filing_.first.assign(map.lanes().size(), 0);
  filing_.mask_slot.assign(map.lanes().size(), 0);
  walkers_.answers.assign(map.crosswalks().size(), 0);
}

void LaneOccupancy::set_step(const OccupancyInputs& inputs) {
  inputs_ = inputs;
  filing_.built = false;
  for (std::uint32_t crosswalk : walkers_.asked) walkers_.answers[crosswalk] = 0;
  walkers_.asked.clear();
}

bool LaneOccupancy::walkers_at(std::uint32_t crosswalk, double walking_speed,
                               double clearance) const {
  Walkers& walkers = walkers_;
  if (walkers.asked.empty()) {
    walkers.walking_speed = walking_speed;
    walkers.clearance = clearance;
  }
  if (walking_speed != walkers.walking_speed || clearance != walkers.clearance)
    return any_walker_at(crosswalk, walking_speed, clearance);
  std::uint8_t& answer = walkers.answers[crosswalk];
  if (answer == 0) {
    answer = any_walker_at(crosswalk, walking_speed, clearance) ? 2 : 1;
    walkers.asked.push_back(crosswalk);
  }
  return answer == 2;
}

bool LaneOccupancy::any_walker_at(std::uint32_t crosswalk, double walking_speed,
                                  double clearance) const {
  const std::vector<MapPoint>& outline = map_->crosswalks()[crosswalk].outline;
  for (std::size_t k = 0; k < inputs_.states.size(); ++k) {
    if (inputs_.kinds[k] != TraceActorKind::pedestrian) continue;
    if (!inputs_.present.empty() && inputs_.present[k] == 0) continue;
    const KinematicState& walker = inputs_.states[k];
    if (walker.speed >= walking_speed && near_polygon({walker.x, walker.y}, outline, clearance))
      return true;
  }
  return false;
}

void LaneOccupancy::build() const {
  Filing& filing = filing_;
  if (filing.built) return;
  filing.built = true;
  for (const auto& entry : filing.filed) {
    filing.first[entry.first] = 0;
    filing.mask_slot[entry.first] = 0;
  }
  filing.filed.clear();
  filing.loose.clear();
  if (filing.segments.size() != inputs_.states.size())
    filing.segments.assign(inputs_.states.size(), std::numeric_limits<std::size_t>::max());
  for (std::size_t k = 0; k < inputs_.states.size(); ++k) {
    if (!inputs_.present.empty() && inputs_.present[k] == 0) continue;
    const auto actor = static_cast<std::uint32_t>(k);
    if (!file_on_lanes(actor)) filing.loose.push_back(actor);
  }
  // By lane, and within a lane in ascending actor order, each actor once (rings lead back to
  // lanes already filed under).
  std::sort(filing.filed.begin(), filing.filed.end());
  filing.filed.erase(std::unique(filing.filed.begin(), filing.filed.end()), filing.filed.end());
  for (std::size_t i = filing.filed.size(); i-- > 0;)
    filing.first[filing.filed[i].first] = static_cast<std::uint32_t>(i + 1);
  make_masks();
}

void LaneOccupancy::make_masks() const {
  Filing& filing = filing_;
  const std::size_t words = (inputs_.states.size() + 63) / 64;
  filing.words = words;
  filing.loose_mask.assign(words, 0);
  for (std::uint32_t k : filing.loose) filing.loose_mask[k / 64] |= std::uint64_t{1} << (k % 64);
  filing.masks.clear();
  std::uint32_t slots = 0;
  for (std::size_t i = 0; i < filing.filed.size(); ++i) {
    const auto [lane, k] = filing.filed[i];
    if (i == 0 || filing.filed[i - 1].first != lane) {
      filing.mask_slot[lane] = ++slots;
      filing.masks.resize(filing.masks.size() + words, 0);
    }
    filing.masks[(slots - 1) * words + k / 64] |= std::uint64_t{1} << (k % 64);
  }
}

void LaneOccupancy::append_on(LaneIndex lane, std::vector<std::uint32_t>& actors) const {
  build();
  const Filing& filing = filing_;
  if (lane >= filing.first.size() || filing.first[lane] == 0) return;
  for (std::size_t i = filing.first[lane] - 1;
       i < filing.filed.size() && filing.filed[i].first == lane; ++i)
    actors.push_back(filing.filed[i].second);
}

void LaneOccupancy::gather(std::span<const LaneIndex> lanes,
                           std::vector<std::uint32_t>& actors) const {
  build();
  const Filing& filing = filing_;
  std::vector<std::uint64_t>& sum = filing_.gathered;
  const std::size_t words = filing.words;
  sum = filing.loose_mask;
  for (LaneIndex lane : lanes) {
    if (lane >= filing.mask_slot.size() || filing.mask_slot[lane] == 0) continue;
    const std::uint64_t* mask = &filing.masks[(filing.mask_slot[lane] - 1) * words];
    for (std::size_t w = 0; w < words; ++w) sum[w] |= mask[w];
  }
  actors.clear();
  for (std::size_t w = 0; w < words; ++w)
    for (std::uint64_t bits = sum[w]; bits != 0; bits &= bits - 1)
      actors.push_back(static_cast<std::uint32_t>(w * 64 + std::countr_zero(bits)));
}

const std::vector<std::uint32_t>& LaneOccupancy::loose() const {
  build();
  return filing_.loose;
}

bool LaneOccupancy::file_on_lanes(std::uint32_t k) const {
  const OccupancyInputs& inputs = inputs_;
  if (inputs.kinds[k] != TraceActorKind::vehicle || inputs.lanes[k].lane < 0) return false;
  const KinematicState& state = inputs.states[k];
  const auto lane_index = static_cast<LaneIndex>(inputs.lanes[k].lane);
  const Lane& lane = map_->lane(lane_index);
  const Polyline& centre = lane.centre_line;
  const double s = inputs.lanes[k].s;
  std::size_t& segment = filing_.segments[k];
  segment =
      segment < centre.segment_count() ? segment_at_from(centre, s, segment) : centre.segment_at(s);
  // The lane's direction there, and the actor's offset from its centre line and heading to it.
  const MapPoint a = centre.points()[segment], b = centre.points()[segment + 1];
  const double length = centre.arc_lengths()[segment + 1] - centre.arc_lengths()[segment];
  if (!(length > 0)) return false;
  const double ux = (b.x - a.x) / length, uy = (b.y - a.y) / length;
  const double lateral = ux * (state.y - a.y) - uy * (state.x - a.x);
  const MapPoint facing = inputs.facings->facing(k);
  const double cos_relative = ux * facing.x + uy * facing.y;
  const double sin_relative = ux * facing.y - uy * facing.x;
  const double half_length = inputs.lengths[k] / 2, half_width = inputs.widths[k] / 2;
  const double across = std::abs(sin_relative) * half_length + std::abs(cos_relative) * half_width;
  const bool moving = state.speed > kPredictedMinSpeed;
  const double travel = moving ? longitudinal_velocity(state) * inputs.prediction_time : 0;
  const double drift = sin_relative * travel;  // sideways to the lane, by the prediction time
  const double left = lane.narrowest_left_width, right = lane.narrowest_right_width;
  for (const double offset : {lateral, lateral + drift})
    if (!(offset + across <= left && offset - across >= -right)) return false;
  filing_.filed.emplace_back(lane_index, k);
  const double extent = half_length + half_width + kAlongMargin;
  const double forward = cos_relative * travel;  // along the lane, by the prediction time
  const double ahead = s + std::max(forward, 0.0) + extent - centre.length();
  if (ahead > 0)
    for (LaneIndex next : lane.successors) file_ahead(next, ahead, k, 1);
  const double behind = extent + std::max(-forward, 0.0) - s;
  if (behind > 0)
    for (LaneIndex previous : lane.predecessors) file_behind(previous, behind, k, 1);
  return true;
}

// Files actor k on `lane`, which its body or predicted body reaches `reach` metres into, and on
// the lanes after it that it reaches.
void LaneOccupancy::file_ahead(LaneIndex lane, double reach, std::uint32_t k, int depth) const {
  filing_.filed.emplace_back(lane, k);
  const double beyond = reach - map_->lane(lane).length();
  if (beyond <= 0 || depth >= kMaxDepth) return;
  for (LaneIndex next : map_->lane(lane).successors) file_ahead(next, beyond, k, depth + 1);
}

// The same backwards: `lane` ends `reach` metres ahead of the body's rear.
void LaneOccupancy::file_behind(LaneIndex lane, double reach, std::uint32_t k, int depth) const {
  filing_.filed.emplace_back(lane, k);
  const double beyond = reach - map_->lane(lane).length();
  if (beyond <= 0 || depth >= kMaxDepth) return;
  for (LaneIndex previous : map_->lane(lane).predecessors)
    file_behind(previous, beyond, k, depth + 1);
}

}  // namespace scenfuzz
