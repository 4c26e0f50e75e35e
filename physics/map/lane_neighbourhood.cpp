// The lane segments around an area, and project_to_lane's inside answer from them alone.
#include "physics/map/lane_neighbourhood.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lang/demand.hpp"

namespace scenfuzz {

namespace {

// m added to every segment's reach: inside allows 1e-9 of rounding between a projection's
// distance and its lateral offset, and the boxes are compared in rounded arithmetic.
constexpr double kReachSlack = 1e-6;

double widest_half_width(const Lane& lane) {
  double widest = 0;
  for (const WidthSample& sample : lane.left_width) widest = std::max(widest, sample.width);
  for (const WidthSample& sample : lane.right_width) widest = std::max(widest, sample.width);
  return widest;
}

// Linear widths between samples never exceed the widest sample, so a point inside the lane at
// a segment is within `reach` (that width and the slack) of it.
NeighbourSegment neighbour(const Lane& lane, LaneIndex index, std::uint32_t k, double reach) {
  const MapPoint a = lane.centre_line.points()[k];
  const MapPoint b = lane.centre_line.points()[k + 1];
  return {{std::min(a.x, b.x) - reach, std::min(a.y, b.y) - reach},
          {std::max(a.x, b.x) + reach, std::max(a.y, b.y) + reach},
          index,
          k};
}

// project_to_lane's projection of `point` onto one segment of a lane, with the same arithmetic
// (lane_queries.cpp's make_projection; the tests compare the two bit for bit).
LaneProjection project_onto(const RoadMap& map, const NeighbourSegment& segment, MapPoint point) {
  const PolylineProjection on =
      map.lane(segment.lane).centre_line.project_to_segment(point, segment.segment);
  LaneProjection projection{segment.lane, on.s, on.lateral, on.distance, false};
  const bool beside = on.distance <= std::abs(on.lateral) + 1e-9;
  projection.inside = beside && on.lateral <= lane_left_width_at(map, segment.lane, on.s) &&
                      -on.lateral <= lane_right_width_at(map, segment.lane, on.s);
  return projection;
}

bool in_box(MapPoint p, MapPoint low, MapPoint high) {
  return p.x >= low.x && p.x <= high.x && p.y >= low.y && p.y <= high.y;
}

// The cells a box meets, clamped to the grid: first and last column and row.
struct CellRange {
  std::uint32_t column_first, column_last, row_first, row_last;
};

std::uint32_t cell_index(double offset, double cell, std::uint32_t count) {
  const double k = offset / cell;
  if (!(k > 0)) return 0;  // also NaN
  // Truncation is the floor here (k > 0), and never decreases with k.
  return static_cast<std::uint32_t>(std::min(k, static_cast<double>(count - 1)));
}

CellRange cells_of(const LaneNeighbourhood& n, MapPoint low, MapPoint high) {
  return {cell_index(low.x - n.low.x, n.cell, n.columns),
          cell_index(high.x - n.low.x, n.cell, n.columns),
          cell_index(low.y - n.low.y, n.cell, n.rows),
          cell_index(high.y - n.low.y, n.cell, n.rows)};
}

// Files every segment in the cells its box meets (counted first, then placed), so that a point
// is tested only against the segments of its own cell. The cell of a point in a box lies within
// the box's cell range, as the cell of a coordinate never decreases with it (rounding included).
void fill_grid(LaneNeighbourhood& n) {
  // m: a few segments' reach per cell (16 m cells filed faster but made the crossroads' lookups
  // cost more than that saved).
  constexpr double kCell = 4;
  constexpr double kMostCells = 65536;  // a larger area gets larger cells
  const double width = n.high.x - n.low.x, height = n.high.y - n.low.y;
  n.cell = std::max(kCell, std::sqrt(width * height / kMostCells));
  n.columns = static_cast<std::uint32_t>(std::floor(width / n.cell)) + 1;
  n.rows = static_cast<std::uint32_t>(std::floor(height / n.cell)) + 1;
  const std::size_t cells = static_cast<std::size_t>(n.columns) * n.rows;
  n.cell_starts.assign(cells + 1, 0);
  auto each_cell = [&](const NeighbourSegment& segment, auto&& visit) {
    const CellRange range = cells_of(n, segment.low, segment.high);
    for (std::uint32_t row = range.row_first; row <= range.row_last; ++row)
      for (std::uint32_t column = range.column_first; column <= range.column_last; ++column)
        visit(static_cast<std::size_t>(row) * n.columns + column);
  };
  for (const NeighbourSegment& segment : n.segments)
    each_cell(segment, [&](std::size_t c) { ++n.cell_starts[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) n.cell_starts[c + 1] += n.cell_starts[c];
  n.cell_segments.resize(n.cell_starts[cells]);
  std::vector<std::uint32_t> next(n.cell_starts.begin(), n.cell_starts.end() - 1);
  for (std::uint32_t k = 0; k < n.segments.size(); ++k)
    each_cell(n.segments[k], [&](std::size_t c) { n.cell_segments[next[c]++] = k; });
}

}  // namespace

LaneNeighbourhood lane_neighbourhood(const RoadMap& map, MapPoint low, MapPoint high) {
  SCENFUZZ_DEMAND(low.x <= high.x && low.y <= high.y);
  LaneNeighbourhood neighbourhood;
  neighbourhood.low = low;
  neighbourhood.high = high;
  // Lane by lane (a map-wide box query of the segment index cost more, at a finely sampled
  // junction, than the lookups it serves): a lane whose first point is farther from the area than
  // its length plus its widest half-width cannot reach it with any segment.
  for (LaneIndex index = 0; index < map.lanes().size(); ++index) {
    const Lane& lane = map.lane(index);
    const auto& points = lane.centre_line.points();
    if (points.size() < 2) continue;
    const double reach = widest_half_width(lane) + kReachSlack;
    const double dx = std::max({low.x - points[0].x, points[0].x - high.x, 0.0});
    const double dy = std::max({low.y - points[0].y, points[0].y - high.y, 0.0});
    if (dx > reach + lane.length() || dy > reach + lane.length()) continue;
    for (std::uint32_t k = 0; k + 1 < points.size(); ++k) {
      NeighbourSegment segment = neighbour(lane, index, k, reach);
      if (segment.high.x < low.x || segment.low.x > high.x || segment.high.y < low.y ||
          segment.low.y > high.y)
        continue;  // no point of the area can be inside its lane at this segment
      neighbourhood.segments.push_back(segment);
    }
  }
  fill_grid(neighbourhood);
  return neighbourhood;
}

LaneNeighbourhood junction_neighbourhood(const RoadMap& map, std::uint32_t junction,
                                         double margin) {
  const auto& outline = map.junctions()[junction].outline;
  if (outline.empty()) return {};
  MapPoint low = outline.front(), high = outline.front();
  for (const MapPoint& p : outline) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y)};
  }
  return lane_neighbourhood(map, {low.x - margin, low.y - margin},
                            {high.x + margin, high.y + margin});
}

bool covers(const LaneNeighbourhood& neighbourhood, MapPoint point) {
  return in_box(point, neighbourhood.low, neighbourhood.high);
}

// project_to_lane's choice among the lanes containing a point, over the same candidates (every
// segment whose projection is inside its lane) and with the same comparison; the first
// candidate's heading is computed only once a second one is found.
std::optional<LaneProjection> lane_containing(const RoadMap& map,
                                              const LaneNeighbourhood& neighbourhood,
                                              MapPoint point, double heading) {
  std::optional<LaneProjection> best;
  double best_difference = std::numeric_limits<double>::infinity();
  bool best_difference_known = false;
  auto difference_of = [&](const LaneProjection& projection) {
    return std::abs(
        angle_difference(heading, map.lane(projection.lane).centre_line.heading_at(projection.s)));
  };
  if (neighbourhood.cell_starts.empty()) return std::nullopt;
  const CellRange cell = cells_of(neighbourhood, point, point);
  const std::size_t c =
      static_cast<std::size_t>(cell.row_first) * neighbourhood.columns + cell.column_first;
  for (std::uint32_t k = neighbourhood.cell_starts[c]; k < neighbourhood.cell_starts[c + 1]; ++k) {
    const NeighbourSegment& segment = neighbourhood.segments[neighbourhood.cell_segments[k]];
    if (!in_box(point, segment.low, segment.high)) continue;
    LaneProjection candidate = project_onto(map, segment, point);
    if (!candidate.inside) continue;
    if (!best) {
      best = candidate;
      continue;
    }
    if (!best_difference_known) {
      best_difference = difference_of(*best);
      best_difference_known = true;
    }
    const double difference = difference_of(candidate);
    const bool better = difference < best_difference - 1e-9 ||
                        (difference <= best_difference + 1e-9 &&
                         (candidate.distance < best->distance ||
                          (candidate.distance == best->distance && candidate.lane < best->lane)));
    if (better) {
      best_difference = std::min(best_difference, difference);
      best = candidate;
    }
  }
  return best;
}

}  // namespace scenfuzz
