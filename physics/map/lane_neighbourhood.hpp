// The lane segments around one area of the map (a junction's outline), kept so that asking which
// lane a point in that area lies in needs no search of the whole map's segment index. The answer
// is project_to_lane's (with a heading) whenever that lies inside a lane: the reference driver
// asks it for every vehicle in a junction twice a second, and the index search (a nearest query
// and a box query per vehicle) cost more than the rest of its junction rule.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "physics/map/lane_queries.hpp"
#include "physics/map/map_point.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

// One centre-line segment with the box a point must lie in to be inside its lane there: the
// segment's bounding box grown by the lane's widest half-width.
struct NeighbourSegment {
  MapPoint low, high;
  LaneIndex lane = 0;
  std::uint32_t segment = 0;
};

// The segments lane by lane, and a uniform grid over the area: cell c lists, ascending, the
// segments whose box meets it, from cell_starts[c] to cell_starts[c + 1] in cell_segments.
struct LaneNeighbourhood {
  MapPoint low{0, 0}, high{-1, -1};  // the area: answers are exact for points in it (none)
  std::vector<NeighbourSegment> segments;
  double cell = 1;  // m, the side of a grid cell
  std::uint32_t columns = 0, rows = 0;
  std::vector<std::uint32_t> cell_starts;
  std::vector<std::uint32_t> cell_segments;
};

// Every segment that could hold a point of the box [low, high] inside its lane.
LaneNeighbourhood lane_neighbourhood(const RoadMap& map, MapPoint low, MapPoint high);

// The neighbourhood of junction `junction`'s outline grown by `margin` on every side (the bounding
// box of the outline); an empty one, covering no point, for a junction without an outline.
LaneNeighbourhood junction_neighbourhood(const RoadMap& map, std::uint32_t junction, double margin);

bool covers(const LaneNeighbourhood& neighbourhood, MapPoint point);

// For a point the neighbourhood covers and a finite heading: project_to_lane(map, point, heading)
// when that projection is inside its lane, nullopt when the point is inside no lane. The same
// candidates and comparison, met in another order (lane by lane, not the index's): the answer can
// differ only where project_to_lane's own depends on its order, between candidates whose heading
// differences lie within its 1e-9 of each other; and for lanes wider than its 10 m each side.
std::optional<LaneProjection> lane_containing(const RoadMap& map,
                                              const LaneNeighbourhood& neighbourhood,
                                              MapPoint point, double heading);

}  // namespace scenfuzz
