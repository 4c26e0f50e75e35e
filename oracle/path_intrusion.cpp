// The intrusion from the path entry, the intruder's standstill and the pair geometry at the moment
// that counts.
#include "oracle/path_intrusion.hpp"

#include <algorithm>

#include "oracle/pair_geometry.hpp"
#include "oracle/path_entry.hpp"
#include "oracle/right_of_way.hpp"
#include "oracle/rss_distances.hpp"
#include "oracle/rss_response.hpp"

namespace scenfuzz {

namespace {

// The first sample of the standstill that lasts up to `last`; nullopt when moving at `last`.
std::optional<std::size_t> rest_since(const TraceActor& actor, std::size_t last) {
  if (actor.speed[last] > kStandstillSpeed) return std::nullopt;
  std::size_t i = last;
  while (i > actor.present_from && actor.speed[i - 1] <= kStandstillSpeed) --i;
  return i;
}

}  // namespace

std::optional<PathIntrusion> path_intrusion(const Trace& trace, const RoadMap& map, ActorId vehicle,
                                            ActorId intruder, std::size_t collision_sample,
                                            const RssParameters& rss) {
  const std::optional<PathEntry> entry =
      path_entry(trace, map, vehicle, intruder, collision_sample);
  if (!entry || entry->from_start) return std::nullopt;
  const std::optional<std::size_t> rest = rest_since(trace.actors[intruder], collision_sample);
  if (rest && *rest < entry->sample) return std::nullopt;  // it stood; the path came to it
  PathIntrusion found;
  found.sample = rest && *rest > entry->sample ? *rest : entry->sample;
  found.came_to_rest = rest && *rest > entry->sample;
  const PairGeometry g = pair_geometry(trace, map, vehicle, intruder, found.sample);
  found.gap = std::max(0.0, g.gap_lon);
  found.speed = std::max(0.0, g.reference_lon);
  found.safe_distance = rss_safe_longitudinal_same(found.speed, std::max(0.0, g.other_lon),
                                                   rss_response_time(vehicle, rss), rss);
  return found;
}

}  // namespace scenfuzz
