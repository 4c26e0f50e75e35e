// The lanes reachable from the entry within two successor links, and the junction conflicts of
// those (oracle/junction_priority.cpp's test: centre lines crossing or a successor shared).
#include "oracle/merge_lanes.hpp"

#include <algorithm>
#include <vector>

#include "oracle/junction_priority.hpp"

namespace scenfuzz {

namespace {

// Successor links followed from the entry: into the connector, and on into the lane it joins.
constexpr int kMergeDepth = 2;

std::vector<LaneIndex> reachable(const RoadMap& map, LaneIndex entry) {
  std::vector<LaneIndex> lanes{entry};
  std::size_t from = 0;
  for (int depth = 0; depth < kMergeDepth; ++depth) {
    const std::size_t to = lanes.size();
    for (std::size_t i = from; i < to; ++i)
      for (const LaneIndex next : map.lane(lanes[i]).successors)
        if (std::find(lanes.begin(), lanes.end(), next) == lanes.end()) lanes.push_back(next);
    from = to;
  }
  return lanes;
}

}  // namespace

bool merges_with(const RoadMap& map, LaneIndex entry, LaneIndex lane) {
  const std::vector<LaneIndex> ahead = reachable(map, entry);
  if (std::find(ahead.begin(), ahead.end(), lane) != ahead.end()) return true;
  return std::any_of(ahead.begin(), ahead.end(),
                     [&](LaneIndex a) { return junction_lanes_conflict(map, a, lane); });
}

}  // namespace scenfuzz
