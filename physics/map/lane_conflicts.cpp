// Crossing and merging lanes (lane_conflicts.hpp).
#include "physics/map/lane_conflicts.hpp"

#include <algorithm>
#include <optional>
#include <vector>

namespace scenfuzz {

namespace {

// m between the end of a merging lane and the lane it runs into: built-in and Apollo maps join
// them exactly; more means the lanes share a successor without meeting.
constexpr double kMergeTolerance = 1.0;

// Arc length along `line` of its first proper crossing with `other`.
std::optional<double> first_crossing(const Polyline& line, const Polyline& other) {
  const auto& p = line.points();
  const auto& q = other.points();
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const MapPoint a = p[i], b = p[i + 1];
    for (std::size_t j = 0; j + 1 < q.size(); ++j) {
      const MapPoint c = q[j], d = q[j + 1];
      const double r_x = b.x - a.x, r_y = b.y - a.y, s_x = d.x - c.x, s_y = d.y - c.y;
      const double denominator = r_x * s_y - r_y * s_x;
      if (denominator == 0) continue;
      const double t = ((c.x - a.x) * s_y - (c.y - a.y) * s_x) / denominator;
      const double u = ((c.x - a.x) * r_y - (c.y - a.y) * r_x) / denominator;
      if (t > 0 && t < 1 && u > 0 && u < 1)
        return line.arc_lengths()[i] + t * (line.arc_lengths()[i + 1] - line.arc_lengths()[i]);
    }
  }
  return std::nullopt;
}

double cross(MapPoint o, MapPoint a, MapPoint b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool segments_cross(MapPoint a, MapPoint b, MapPoint c, MapPoint d) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

struct Box {
  MapPoint low, high;
};

bool boxes_meet(const Box& a, const Box& b) {
  return a.low.x <= b.high.x && b.low.x <= a.high.x && a.low.y <= b.high.y && b.low.y <= a.high.y;
}

Box box_of(const std::vector<MapPoint>& points, std::size_t from, std::size_t to) {
  Box box{points[from], points[from]};
  for (std::size_t k = from + 1; k <= to; ++k) {
    box.low = {std::min(box.low.x, points[k].x), std::min(box.low.y, points[k].y)};
    box.high = {std::max(box.high.x, points[k].x), std::max(box.high.y, points[k].y)};
  }
  return box;
}

// Segments per run: junction lanes are sampled finely (hundreds of segments), and most pairs of
// them meet, if at all, in one place.
constexpr std::size_t kRun = 8;

// The boxes of a line's runs of kRun segments (run r: segments r * kRun .. r * kRun + kRun - 1).
std::vector<Box> run_boxes(const std::vector<MapPoint>& points) {
  const std::size_t segments = points.size() - 1;
  std::vector<Box> runs;
  runs.reserve((segments + kRun - 1) / kRun);
  for (std::size_t first = 0; first < segments; first += kRun)
    runs.push_back(box_of(points, first, std::min(first + kRun, segments)));
  return runs;
}

// Segments whose boxes do not meet cannot cross (the same answer, without the cross products for
// most pairs): only pairs of runs whose boxes meet have their segments compared.
bool runs_cross(const std::vector<MapPoint>& p, const std::vector<Box>& p_runs,
                const std::vector<MapPoint>& q, const std::vector<Box>& q_runs) {
  for (std::size_t a = 0; a < p_runs.size(); ++a) {
    for (std::size_t b = 0; b < q_runs.size(); ++b) {
      if (!boxes_meet(p_runs[a], q_runs[b])) continue;
      for (std::size_t i = a * kRun; i < std::min((a + 1) * kRun, p.size() - 1); ++i) {
        const Box mine = box_of(p, i, i + 1);
        if (!boxes_meet(mine, q_runs[b])) continue;
        for (std::size_t j = b * kRun; j < std::min((b + 1) * kRun, q.size() - 1); ++j)
          if (boxes_meet(mine, box_of(q, j, j + 1)) &&
              segments_cross(p[i], p[i + 1], q[j], q[j + 1]))
            return true;
      }
    }
  }
  return false;
}

}  // namespace

bool lines_cross(const Polyline& first, const Polyline& second) {
  const auto& p = first.points();
  const auto& q = second.points();
  if (p.size() < 2 || q.size() < 2) return false;
  return runs_cross(p, run_boxes(p), q, run_boxes(q));
}

bool shares_successor(const Lane& first, const Lane& second) {
  return std::any_of(first.successors.begin(), first.successors.end(), [&](LaneIndex next) {
    return std::find(second.successors.begin(), second.successors.end(), next) !=
           second.successors.end();
  });
}

std::vector<LaneIndex> conflicting_lanes(const RoadMap& map, LaneIndex lane) {
  const Lane& mine = map.lane(lane);
  std::vector<LaneIndex> conflicts;
  if (!mine.junction) return conflicts;
  // lines_cross against each of the junction's lanes, with this lane's run boxes made once.
  const auto& p = mine.centre_line.points();
  const std::vector<Box> p_runs = p.size() < 2 ? std::vector<Box>{} : run_boxes(p);
  for (LaneIndex other = 0; other < map.lanes().size(); ++other) {
    const Lane& candidate = map.lane(other);
    if (other == lane || candidate.junction != mine.junction) continue;
    const auto& q = candidate.centre_line.points();
    if (shares_successor(mine, candidate) ||
        (!p_runs.empty() && q.size() >= 2 && runs_cross(p, p_runs, q, run_boxes(q))))
      conflicts.push_back(other);
  }
  return conflicts;
}

std::vector<ConflictPoint> conflict_points(const RoadMap& map, std::span<const LaneIndex> own,
                                           std::span<const LaneIndex> conflicts) {
  std::vector<ConflictPoint> points;
  for (LaneIndex other : conflicts) {
    const Polyline& line = map.lane(other).centre_line;
    for (LaneIndex mine : own) {
      // The ego's path along the lane itself (a roundabout's ring, from its entry to its exit)
      // meets it nowhere: what is on it ahead of the ego is followed, not given way to.
      if (mine == other) continue;
      const Polyline& path = map.lane(mine).centre_line;
      if (const std::optional<double> crossing = first_crossing(line, path)) {
        points.push_back({other, *crossing});
        continue;
      }
      // Merging only where `mine` ends on the other lane: two roundabout entries that run into
      // the ring at opposite sides share a successor but never meet, nor does an exit leaving
      // the ring.
      const PolylineProjection merge = line.project(path.points().back());
      if (merge.distance <= kMergeTolerance) points.push_back({other, merge.s});
    }
  }
  return points;
}

}  // namespace scenfuzz
