// find_junction_sites (outline_junction_sites.hpp): every crossing of two roads' centre lines,
// each carried on past its ends, read as a junction with each road's stretch inside it.
#include "physics/map/outline_junction_sites.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "physics/map/road_map.hpp"

namespace scenfuzz::outline {

namespace {

constexpr double kEndReach = 1.5;
// Room for a bus or a truck to turn right round the corner at its full lock: a kerb-to-kerb
// turn's radius is this plus half a lane, 7.75 m for 3.5 m lanes (a truck's full lock: 6 m).
constexpr double kTurningMargin = 6.0;
constexpr double kSmallestAngle = 30 * std::numbers::pi / 180;
constexpr double kContinuationAngle = 60 * std::numbers::pi / 180;
// Crossings this close are one: a centre line crossing another at a vertex crosses two segments.
constexpr double kSamePlace = 0.01;

double interpolated(const RoadShape& road, const std::vector<double>& widths, double s) {
  const std::vector<CentreSample>& samples = road.samples;
  if (s <= samples.front().s) return widths.front();
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (s <= samples[i].s) {
      const double t = (s - samples[i - 1].s) / (samples[i].s - samples[i - 1].s);
      return widths[i - 1] + t * (widths[i] - widths[i - 1]);
    }
  return widths.back();
}

// The wider half's width at station s (clamped to the road).
double half_width_at(const RoadShape& road, double s) {
  return std::max(interpolated(road, road.right_widths, s),
                  interpolated(road, road.left_widths, s));
}

double widest_half(const RoadShape& road) {
  return std::max(*std::max_element(road.right_widths.begin(), road.right_widths.end()),
                  *std::max_element(road.left_widths.begin(), road.left_widths.end()));
}

// The centre line carried `reach` metres straight on past both its ends.
std::vector<MapPoint> extended(const Polyline& line, double reach) {
  std::vector<MapPoint> points = line.points();
  const double first = line.heading_at(0), last = line.heading_at(line.length());
  points.front() = {points.front().x - reach * std::cos(first),
                    points.front().y - reach * std::sin(first)};
  points.back() = {points.back().x + reach * std::cos(last),
                   points.back().y + reach * std::sin(last)};
  return points;
}

struct Crossing {
  MapPoint point;
  double s_a = 0, s_b = 0;  // stations on the roads, beyond an end where a line was carried on
};

// Where segment p0-p1 crosses q0-q1: the fractions along each, or none (parallel or apart).
std::optional<std::pair<double, double>> segment_crossing(MapPoint p0, MapPoint p1, MapPoint q0,
                                                          MapPoint q1) {
  const double rx = p1.x - p0.x, ry = p1.y - p0.y, sx = q1.x - q0.x, sy = q1.y - q0.y;
  const double denominator = rx * sy - ry * sx;
  if (std::abs(denominator) < 1e-12) return std::nullopt;
  const double qx = q0.x - p0.x, qy = q0.y - p0.y;
  const double t = (qx * sy - qy * sx) / denominator;
  const double u = (qx * ry - qy * rx) / denominator;
  if (t < 0 || t > 1 || u < 0 || u > 1) return std::nullopt;
  return std::pair{t, u};
}

std::vector<double> arc_lengths(const std::vector<MapPoint>& points) {
  std::vector<double> arc{0};
  for (std::size_t i = 1; i < points.size(); ++i)
    arc.push_back(arc.back() + distance(points[i - 1], points[i]));
  return arc;
}

std::vector<Crossing> crossings(const RoadShape& a, const RoadShape& b) {
  const double reach_a = widest_half(b) + kEndReach, reach_b = widest_half(a) + kEndReach;
  const std::vector<MapPoint> pa = extended(a.centre, reach_a), pb = extended(b.centre, reach_b);
  const std::vector<double> arc_a = arc_lengths(pa), arc_b = arc_lengths(pb);
  std::vector<Crossing> found;
  for (std::size_t i = 0; i + 1 < pa.size(); ++i)
    for (std::size_t j = 0; j + 1 < pb.size(); ++j) {
      const auto fractions = segment_crossing(pa[i], pa[i + 1], pb[j], pb[j + 1]);
      if (!fractions) continue;
      const auto [t, u] = *fractions;
      const MapPoint point{pa[i].x + t * (pa[i + 1].x - pa[i].x),
                           pa[i].y + t * (pa[i + 1].y - pa[i].y)};
      const bool seen = std::any_of(found.begin(), found.end(), [&](const Crossing& crossing) {
        return distance(crossing.point, point) < kSamePlace;
      });
      if (!seen)
        found.push_back({point, arc_a[i] + t * (arc_a[i + 1] - arc_a[i]) - reach_a,
                         arc_b[j] + u * (arc_b[j + 1] - arc_b[j]) - reach_b});
    }
  return found;
}

std::string place(MapPoint point) { return "(" + metres(point.x) + ", " + metres(point.y) + ")"; }

// The road's stretch inside the junction, `reach` either side of station s.
JunctionLeg leg(std::size_t index, const RoadShape& road, double s, double reach,
                const RoadShape& other, MapPoint point) {
  const double length = road.centre.length();
  const bool before = s - reach > 0, after = s + reach < length;
  if (!before && !after)
    throw MapError("road '" + road.name + "': it is too short to leave its junction with road '" +
                   other.name + "' at " + place(point) + ", which reaches " + metres(reach) +
                   " m along it either side");
  if (!after) return {index, LegKind::ends, s - reach, length};
  if (!before) return {index, LegKind::starts, 0, s + reach};
  return {index, LegKind::through, s - reach, s + reach};
}

// Roads meeting end to start, near enough in heading that one continues into the other.
bool continuation(const JunctionLeg& a, const JunctionLeg& b, double angle) {
  const bool end_to_start = (a.kind == LegKind::ends && b.kind == LegKind::starts) ||
                            (a.kind == LegKind::starts && b.kind == LegKind::ends);
  return end_to_start && angle < kContinuationAngle;
}

std::optional<JunctionSite> site(const std::vector<RoadShape>& roads, std::size_t ia,
                                 std::size_t ib, const Crossing& crossing) {
  const RoadShape &a = roads[ia], &b = roads[ib];
  const double sa = std::clamp(crossing.s_a, 0.0, a.centre.length());
  const double sb = std::clamp(crossing.s_b, 0.0, b.centre.length());
  const double angle = std::abs(angle_difference(a.centre.heading_at(sa), b.centre.heading_at(sb)));
  const double sine = std::max(std::sin(angle), 1e-6), cotangent = std::abs(std::cos(angle)) / sine;
  const double wa = half_width_at(a, sa), wb = half_width_at(b, sb);
  const double reach_a = wb / sine + wa * cotangent + kTurningMargin;
  const double reach_b = wa / sine + wb * cotangent + kTurningMargin;
  // Classified with the stations as found, so that a road ending at the other's edge ends there.
  const auto kind_of = [](double s, double reach, double length) {
    return s + reach >= length ? LegKind::ends
           : s - reach <= 0    ? LegKind::starts
                               : LegKind::through;
  };
  const JunctionLeg probe_a{ia, kind_of(crossing.s_a, reach_a, a.centre.length())};
  const JunctionLeg probe_b{ib, kind_of(crossing.s_b, reach_b, b.centre.length())};
  if (continuation(probe_a, probe_b, angle)) return std::nullopt;
  if (angle < kSmallestAngle || angle > std::numbers::pi - kSmallestAngle)
    throw MapError("road '" + a.name + "': it meets road '" + b.name + "' at " +
                   place(crossing.point) + " at " + metres(angle * 180 / std::numbers::pi) +
                   " degrees; scenfuzz makes a junction only of roads meeting at 30 degrees or "
                   "more");
  return JunctionSite{"junction_" + a.name + "_" + b.name,
                      crossing.point,
                      {leg(ia, a, crossing.s_a, reach_a, b, crossing.point),
                       leg(ib, b, crossing.s_b, reach_b, a, crossing.point)}};
}

// No two junctions' stretches overlap on any road.
void check_apart(const std::vector<RoadShape>& roads, const std::vector<JunctionSite>& sites) {
  for (std::size_t r = 0; r < roads.size(); ++r) {
    std::vector<std::pair<const JunctionLeg*, const JunctionSite*>> legs;
    for (const JunctionSite& site : sites)
      for (const JunctionLeg& leg : site.legs)
        if (leg.road == r) legs.push_back({&leg, &site});
    std::sort(legs.begin(), legs.end(),
              [](const auto& x, const auto& y) { return x.first->begin < y.first->begin; });
    for (std::size_t i = 1; i < legs.size(); ++i)
      if (legs[i].first->begin < legs[i - 1].first->end)
        throw MapError("road '" + roads[r].name + "': its junctions at " +
                       place(legs[i - 1].second->centre) + " and " + place(legs[i].second->centre) +
                       " overlap along it; scenfuzz needs each junction clear of the next");
  }
}

}  // namespace

std::vector<JunctionSite> find_junction_sites(const std::vector<RoadShape>& roads) {
  std::vector<JunctionSite> sites;
  for (std::size_t a = 0; a < roads.size(); ++a)
    for (std::size_t b = a + 1; b < roads.size(); ++b) {
      std::size_t meetings = 0;
      for (const Crossing& crossing : crossings(roads[a], roads[b]))
        if (std::optional<JunctionSite> found = site(roads, a, b, crossing)) {
          if (++meetings > 1) found->id += "_" + std::to_string(meetings);
          sites.push_back(std::move(*found));
        }
    }
  check_apart(roads, sites);
  return sites;
}

}  // namespace scenfuzz::outline
