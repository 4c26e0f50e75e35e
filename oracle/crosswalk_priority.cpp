// The ego "reaches" a crosswalk when its centre comes within half its length of the outline; the
// pedestrian is on it from the start of the stretch that lasts until the impact.
#include "oracle/crosswalk_priority.hpp"

#include "oracle/junction_priority.hpp"
#include "physics/map/polygon.hpp"

namespace scenfuzz {

namespace {

bool on(const TraceActor& actor, std::size_t i, const Crosswalk& crosswalk, double margin) {
  return near_polygon({actor.x[i], actor.y[i]}, crosswalk.outline, margin);
}

// The first sample of the stretch up to `k` during which `actor` is on the crosswalk.
std::size_t on_since(const TraceActor& actor, std::size_t k, const Crosswalk& crosswalk,
                     double margin) {
  std::size_t i = k;
  while (i > actor.present_from && on(actor, i - 1, crosswalk, margin)) --i;
  return i;
}

}  // namespace

std::optional<CrosswalkPriority> crosswalk_priority(const Trace& trace, const RoadMap& map,
                                                    ActorId pedestrian, std::size_t k,
                                                    double memory) {
  const TraceActor& ego = trace.actors[kEgo];
  const TraceActor& walker = trace.actors[pedestrian];
  const auto window = static_cast<std::size_t>(memory / trace.dt);
  const std::size_t first = k > window ? k - window : 0;
  const std::optional<LaneIndex> lane = last_junction_lane(trace, map, kEgo, first, k);
  if (!lane || map.lane(*lane).turn == LaneTurn::none) return std::nullopt;
  for (std::uint32_t c = 0; c < map.crosswalks().size(); ++c) {
    const Crosswalk& crosswalk = map.crosswalks()[c];
    if (!on(walker, k, crosswalk, 0) || !on(ego, k, crosswalk, ego.length / 2)) continue;
    const std::size_t walker_on = on_since(walker, k, crosswalk, 0);
    const std::size_t ego_on = on_since(ego, k, crosswalk, ego.length / 2);
    if (walker_on > ego_on) continue;  // the ego was there first; the pedestrian walked into it
    return CrosswalkPriority{c, map.lane(*lane).turn, trace.time[ego_on] - trace.time[walker_on]};
  }
  return std::nullopt;
}

}  // namespace scenfuzz
