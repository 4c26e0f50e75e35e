// A path entry from the pair geometry, scanning back from the collision.
#include "oracle/path_entry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "oracle/pair_geometry.hpp"

namespace scenfuzz {

namespace {

constexpr double kSideImpactLookBack = 0.5;  // s

bool in_path(const PairGeometry& g) { return g.gap_lat < 0 && g.dx > 0; }

}  // namespace

std::optional<PathEntry> path_entry(const Trace& trace, const RoadMap& map, ActorId vehicle,
                                    ActorId other, std::size_t collision_sample) {
  const std::size_t first =
      std::max(trace.actors[vehicle].present_from, trace.actors[other].present_from);
  const auto look_back = static_cast<std::size_t>(std::ceil(kSideImpactLookBack / trace.dt));
  std::size_t last = collision_sample + 1;
  for (std::size_t i = collision_sample + 1; i-- > first && collision_sample - i <= look_back;)
    if (in_path(pair_geometry(trace, map, vehicle, other, i))) {
      last = i;
      break;
    }
  if (last > collision_sample) return std::nullopt;
  std::size_t entry = last;
  while (entry > first && in_path(pair_geometry(trace, map, vehicle, other, entry - 1))) --entry;
  const PairGeometry g = pair_geometry(trace, map, vehicle, other, entry);
  PathEntry found;
  found.sample = entry;
  found.time = trace.time[entry];
  found.gap = std::max(0.0, g.gap_lon);
  found.closing_speed = g.reference_lon - g.other_lon;
  found.time_to_collision = found.closing_speed > 0 ? found.gap / found.closing_speed
                                                    : std::numeric_limits<double>::infinity();
  found.required_deceleration = found.closing_speed <= 0 ? 0
                                : found.gap > 0
                                    ? found.closing_speed * found.closing_speed / (2 * found.gap)
                                    : std::numeric_limits<double>::infinity();
  found.from_start = entry == first;
  return found;
}

}  // namespace scenfuzz
