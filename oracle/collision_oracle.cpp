// The collision oracle: how close the ego comes to any other body, with penetration counted
// negative, so that the search can approach a collision continuously and "robustness < 0" means
// exactly "the ego touched something deeper than contact".
#include "oracle/collision_oracle.hpp"

#include <limits>

#include "physics/trace/trace_footprint.hpp"

namespace scenfuzz {

namespace {

struct NearestBody {
  double distance = std::numeric_limits<double>::infinity();
  ActorId actor = kEgo;
};

NearestBody nearest_body(const Trace& trace, std::size_t sample,
                         std::span<const std::size_t> excused_from = {}) {
  NearestBody nearest;
  const Footprint ego = footprint_at(trace, kEgo, sample);
  for (std::size_t other = 1; other < trace.actors.size(); ++other) {
    if (!present_at(trace.actors[other], sample)) continue;  // background traffic off the map
    if (other < excused_from.size() && sample >= excused_from[other]) continue;
    const auto id = static_cast<ActorId>(other);
    const double distance = signed_distance(ego, footprint_at(trace, id, sample));
    if (distance < nearest.distance) nearest = {distance, id};
  }
  return nearest;
}

}  // namespace

std::vector<double> ego_clearance(const Trace& trace) {
  std::vector<double> clearance(trace.sample_count(), std::numeric_limits<double>::infinity());
  if (trace.actors.empty()) return clearance;
  for (std::size_t i = 0; i < clearance.size(); ++i) clearance[i] = nearest_body(trace, i).distance;
  return clearance;
}

CollisionVerdict collision_verdict(const Trace& trace) { return collision_verdict(trace, {}); }

CollisionVerdict collision_verdict(const Trace& trace, std::span<const std::size_t> excused_from) {
  CollisionVerdict verdict;
  verdict.robustness = std::numeric_limits<double>::infinity();
  if (trace.actors.size() < 2) return verdict;
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    const NearestBody nearest = nearest_body(trace, i, excused_from);
    if (nearest.distance < verdict.robustness) verdict = {nearest.distance, i, nearest.actor};
  }
  return verdict;
}

}  // namespace scenfuzz
