// The next junction stretch of a route (junction_stretch.hpp).
#include "physics/map/junction_stretch.hpp"

#include "lang/demand.hpp"

namespace scenfuzz {

std::optional<JunctionStretch> junction_stretch_ahead(const RoadMap& map,
                                                      std::span<const RouteSegment> segments,
                                                      std::span<const double> starts, double from) {
  SCENFUZZ_DEMAND(segments.size() == starts.size());
  auto end_of = [&](std::size_t k) { return starts[k] + segments[k].s_end - segments[k].s_begin; };
  for (std::size_t k = 0; k < segments.size(); ++k) {
    auto junction = map.lane(segments[k].lane).junction;
    if (!junction || end_of(k) <= from) continue;
    std::size_t last = k;
    while (last + 1 < segments.size() && map.lane(segments[last + 1].lane).junction == junction)
      ++last;
    if (end_of(last) <= from) {
      k = last;
      continue;
    }
    return JunctionStretch{k, last, starts[k], end_of(last), *junction};
  }
  return std::nullopt;
}

}  // namespace scenfuzz
