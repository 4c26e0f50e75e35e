// key_moment and its look-ups. Distances between bodies are footprint gaps, as the collision
// oracle measures them, so "nearest" means the same here as in a no_collision verdict.
#include "physics/trace/trace_moment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/collision/footprint.hpp"
#include "physics/trace/trace_footprint.hpp"

namespace scenfuzz {
namespace {

bool finite_heading(const TraceActor& actor, std::size_t i) {
  return i < actor.heading.size() && std::isfinite(actor.heading[i]);
}

}  // namespace

double gap_to_ego(const Trace& trace, ActorId id, std::size_t i) {
  if (!drawn_at(trace, kEgo, i) || !drawn_at(trace, id, i))
    return std::numeric_limits<double>::infinity();
  if (!finite_heading(trace.actors[kEgo], i) || !finite_heading(trace.actors[id], i))
    return distance({trace.actors[kEgo].x[i], trace.actors[kEgo].y[i]},
                    {trace.actors[id].x[i], trace.actors[id].y[i]});
  return signed_distance(footprint_at(trace, kEgo, i), footprint_at(trace, id, i));
}

namespace {

MapPoint ego_at(const Trace& trace, std::size_t i) {
  return {trace.actors[kEgo].x[i], trace.actors[kEgo].y[i]};
}

// The last sample at or before i where the ego is drawn (the first after it when none).
std::optional<std::size_t> ego_sample_near(const Trace& trace, std::size_t i) {
  for (std::size_t j = i + 1; j-- > 0;)
    if (drawn_at(trace, kEgo, j)) return j;
  for (std::size_t j = i + 1; j < trace.sample_count(); ++j)
    if (drawn_at(trace, kEgo, j)) return j;
  return std::nullopt;
}

}  // namespace

std::size_t sample_at(const Trace& trace, double time) {
  const auto at = std::lower_bound(trace.time.begin(), trace.time.end(), time - 1e-9);
  return std::min(static_cast<std::size_t>(at - trace.time.begin()), trace.time.size() - 1);
}

bool drawn_at(const Trace& trace, std::size_t id, std::size_t i) {
  const TraceActor& actor = trace.actors[id];
  return i < actor.x.size() && i < actor.y.size() && present_at(actor, i) &&
         std::isfinite(actor.x[i]) && std::isfinite(actor.y[i]);
}

std::optional<ActorId> nearest_to_ego(const Trace& trace, std::size_t i) {
  std::optional<ActorId> nearest;
  double best = std::numeric_limits<double>::infinity();
  for (ActorId id = 1; id < trace.actors.size(); ++id) {
    const double gap = gap_to_ego(trace, id, i);
    if (gap < best) {
      best = gap;
      nearest = id;
    }
  }
  return nearest;
}

std::optional<TraceMoment> key_moment(const Trace& trace, std::optional<double> verdict_time) {
  if (trace.sample_count() == 0 || trace.actors.empty()) return std::nullopt;
  for (std::size_t c = 0; c < trace.collisions.size(); ++c) {
    const Collision& collision = trace.collisions[c];
    if (collision.first != kEgo && collision.second != kEgo) continue;
    const std::size_t sample = sample_at(trace, collision.time);
    const ActorId other = collision.first == kEgo ? collision.second : collision.first;
    const bool finite_point = std::isfinite(collision.point.x) && std::isfinite(collision.point.y);
    if (!finite_point && !drawn_at(trace, kEgo, sample)) continue;
    return TraceMoment{MomentKind::collision,
                       sample,
                       collision.time,
                       finite_point ? collision.point : ego_at(trace, sample),
                       other,
                       c};
  }
  MomentKind kind = MomentKind::end;
  std::size_t sample = trace.sample_count() - 1;
  if (verdict_time && std::isfinite(*verdict_time)) {
    kind = MomentKind::verdict;
    sample = sample_at(trace, *verdict_time);
  } else {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < trace.sample_count(); ++i)
      if (const std::optional<ActorId> id = nearest_to_ego(trace, i)) {
        const double gap = gap_to_ego(trace, *id, i);
        if (gap < best) {
          best = gap;
          sample = i;
          kind = MomentKind::nearest_approach;
        }
      }
  }
  const std::optional<std::size_t> ego_sample = ego_sample_near(trace, sample);
  if (!ego_sample) return std::nullopt;
  sample = *ego_sample;
  return TraceMoment{
      kind,        sample, trace.time[sample], ego_at(trace, sample), nearest_to_ego(trace, sample),
      std::nullopt};
}

}  // namespace scenfuzz
