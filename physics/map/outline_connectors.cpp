// add_junction (outline_connectors.hpp): turn connectors between a junction's arms, drawn as
// Bezier curves, and the junction's outline as the hull of the arms' edges.
#include "physics/map/outline_connectors.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "physics/map/plane_vectors.hpp"

namespace scenfuzz::outline {

namespace {

constexpr double kStraightOn = 30 * std::numbers::pi / 180;
constexpr double kConnectorSpacing = 0.5;  // metres between a connector's points, at most

using namespace plane;

double end_heading(const std::vector<MapPoint>& line, bool at_start) {
  const std::size_t n = line.size();
  return at_start ? heading_of(line[1] - line[0]) : heading_of(line[n - 1] - line[n - 2]);
}

// The turn from `from` into `to`, seen driving in on `from`: left, right or none (straight on, or
// back the way it came).
LaneTurn turn_between(const JunctionArm& from, const JunctionArm& to) {
  const double turn = angle_difference(heading_of(to.outward), heading_of(-1 * from.outward));
  if (std::abs(turn) < kStraightOn || std::abs(turn) > std::numbers::pi - kStraightOn)
    return LaneTurn::none;
  return turn > 0 ? LaneTurn::left : LaneTurn::right;
}

// The cubic Bezier from p0 heading h0 to p1 heading h1 whose control arms, (4/3) tan(delta / 4)
// of the radius of the circle through both, make it a circular arc within 0.03 % where the two
// headings turn symmetrically.
std::vector<MapPoint> bezier(MapPoint p0, double h0, MapPoint p1, double h1) {
  const double chord = distance(p0, p1);
  const double delta = std::abs(angle_difference(h1, h0));
  const double radius = chord / (2 * std::max(std::sin(delta / 2), 1e-6));
  const double arm = std::min(4.0 / 3 * std::tan(delta / 4) * radius, chord);
  const MapPoint c0 = p0 + arm * unit_vector(h0), c1 = p1 - arm * unit_vector(h1);
  const auto steps =
      static_cast<std::size_t>(std::max(8.0, std::ceil(1.5 * chord / kConnectorSpacing)));
  std::vector<MapPoint> points;
  for (std::size_t i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(steps), u = 1 - t;
    points.push_back((u * u * u * p0 + 3 * u * u * t * c0) + (3 * u * t * t * c1 + t * t * t * p1));
  }
  return points;
}

// Width samples growing linearly from `start` to `end` along `line`, and the boundaries they draw.
void set_widths(LaneDescription& lane, double start, double end) {
  const std::vector<MapPoint>& line = lane.centre_line;
  const double length = length_of(line);
  double s = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (i > 0) s += distance(line[i - 1], line[i]);
    const double width = start + (end - start) * s / length;
    lane.left_width.push_back({s, width});
    const std::size_t a = i == 0 ? 0 : i - 1, b = i == 0 ? 1 : i;
    const MapPoint left = left_normal(unit_vector(heading_of(line[b] - line[a])));
    lane.left_boundary.push_back(line[i] + width * left);
    lane.right_boundary.push_back(line[i] - width * left);
  }
  lane.right_width = lane.left_width;
}

LaneDescription connector(const LaneDescription& in, const LaneDescription& out, LaneTurn turn,
                          const std::string& junction) {
  LaneDescription lane;
  lane.id = in.id + "_to_" + out.id;
  lane.centre_line = bezier(in.centre_line.back(), end_heading(in.centre_line, false),
                            out.centre_line.front(), end_heading(out.centre_line, true));
  set_widths(lane, in.left_width.back().width, out.left_width.front().width);
  lane.speed_limit = in.speed_limit;
  lane.turn = turn;
  lane.junction = junction;
  return lane;
}

// The lane of `lanes` a turn uses: next to the centre line for a left turn, the kerb lane for a
// right turn.
const std::string& turning_lane(const std::vector<std::string>& lanes, LaneTurn turn) {
  return turn == LaneTurn::left ? lanes.front() : lanes.back();
}

// Andrew's monotone chain: the hull counter-clockwise, without collinear points.
std::vector<MapPoint> convex_hull(std::vector<MapPoint> points) {
  std::sort(points.begin(), points.end(),
            [](MapPoint a, MapPoint b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  std::vector<MapPoint> hull(2 * points.size());
  std::size_t k = 0;
  const auto turns_left = [&](std::size_t size, MapPoint p) {
    return cross(hull[size - 1] - hull[size - 2], p - hull[size - 2]) > 1e-9;
  };
  for (MapPoint p : points) {
    while (k >= 2 && !turns_left(k, p)) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && !turns_left(k, points[i])) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace

void add_junction(MapDescription& map, const std::string& id,
                  const std::vector<JunctionArm>& arms) {
  std::vector<MapPoint> edges;
  for (const JunctionArm& from : arms) {
    edges.insert(edges.end(), from.edges.begin(), from.edges.end());
    if (from.in_lanes.empty()) continue;
    for (const JunctionArm& to : arms) {
      const LaneTurn turn = &to == &from ? LaneTurn::none : turn_between(from, to);
      if (turn == LaneTurn::none || to.out_lanes.empty()) continue;
      map.lanes.push_back(connector(lane_named(map, turning_lane(from.in_lanes, turn)),
                                    lane_named(map, turning_lane(to.out_lanes, turn)), turn, id));
    }
  }
  map.junctions.push_back({id, convex_hull(std::move(edges))});
}

}  // namespace scenfuzz::outline
