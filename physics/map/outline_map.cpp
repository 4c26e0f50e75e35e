// describe_outline_map (outline_map.hpp): checks each road outline, makes the lanes of its two
// halves with their ids, neighbours and boundary types, then connects lanes whose ends meet.
#include "physics/map/outline_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <utility>

#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "physics/map/outline_connectors.hpp"
#include "physics/map/outline_half_road.hpp"
#include "physics/map/outline_junction_sites.hpp"
#include "physics/map/outline_signals.hpp"
#include "physics/map/polyline.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

namespace {

using outline::CentreSample;
using outline::HalfSide;
using outline::JunctionSite;
using outline::metres;

// Stations closer than this are one cut (outline_half_road.cpp's sample tolerance).
constexpr double kSameStation = 1e-3;

constexpr const char* kSource = "CH-Scenario road network";
// A boundary point this close to the wrong side of the centre line is drawing noise, not a
// crossing (a one-way road's left boundary is its centre line, drawn with other points).
constexpr double kSideTolerance = 0.01;
constexpr double kConnectionReach = 1.5;
constexpr double kConnectionAngle = 60 * std::numbers::pi / 180;

[[noreturn]] void fail(const std::string& road, const std::string& message) {
  throw MapError("road '" + road + "': " + message);
}

std::string point_text(std::size_t index, MapPoint point) {
  return "point " + std::to_string(index + 1) + " (" + metres(point.x) + ", " + metres(point.y) +
         ")";
}

void check_points(const std::string& road, const char* line, const std::vector<MapPoint>& points) {
  if (points.size() < 2)
    fail(road, std::string("the ") + line + " needs at least two points, it has " +
                   std::to_string(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
      fail(road, "point " + std::to_string(i + 1) + " of the " + line + " is not finite (" +
                     format_number(points[i].x) + ", " + format_number(points[i].y) + ")");
}

Polyline centre_polyline(const RoadOutlineGeometry& road) {
  try {
    return Polyline(road.centre_line);
  } catch (const std::invalid_argument&) {
    fail(road.name, "the centre line has zero length (all its points are at (" +
                        metres(road.centre_line[0].x) + ", " + metres(road.centre_line[0].y) +
                        "))");
  }
}

// Every point of a boundary on its own side of the centre line: `side` +1 left, -1 right.
void check_side(const std::string& road, const Polyline& centre, const char* line,
                const std::vector<MapPoint>& boundary, double side) {
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const double wrong_way = -side * outline::side_of_centre_line(centre, boundary[i]);
    if (wrong_way > kSideTolerance)
      fail(road, point_text(i, boundary[i]) + " of the " + line + " lies " + metres(wrong_way) +
                     " m " + (side > 0 ? "right" : "left") +
                     " of the centre line: the boundary crosses to the other side");
  }
}

HalfSide other(HalfSide side) { return side == HalfSide::right ? HalfSide::left : HalfSide::right; }

// A road checked and measured: its shape, with the junction cuts among its samples once they are
// known, and the lanes of its halves.
struct MeasuredRoad {
  const RoadOutlineGeometry* given = nullptr;
  outline::RoadShape shape;
  int forward = 0, backward = 0;

  int lanes(HalfSide side) const { return side == HalfSide::right ? forward : backward; }
  const std::vector<double>& widths(HalfSide side) const {
    return side == HalfSide::right ? shape.right_widths : shape.left_widths;
  }
};

MeasuredRoad measure(const RoadOutlineGeometry& road) {
  check_points(road.name, "left boundary", road.left_boundary);
  check_points(road.name, "centre line", road.centre_line);
  check_points(road.name, "right boundary", road.right_boundary);
  MeasuredRoad measured{&road, {road.name, centre_polyline(road), {}, {}, {}}};
  const Polyline& centre = measured.shape.centre;
  check_side(road.name, centre, "left boundary", road.left_boundary, +1);
  check_side(road.name, centre, "right boundary", road.right_boundary, -1);
  measured.shape.samples = outline::sample_centre_line(centre);
  measured.shape.right_widths = outline::half_widths(measured.shape.samples, road.right_boundary);
  measured.shape.left_widths = outline::half_widths(measured.shape.samples, road.left_boundary);
  measured.forward = outline::half_lane_count(measured.shape.samples, measured.shape.right_widths);
  measured.backward = outline::half_lane_count(measured.shape.samples, measured.shape.left_widths);
  if (measured.forward == 0 && measured.backward == 0)
    fail(road.name, "the road has no lanes: both halves are narrower than " +
                        metres(outline::kMinimumHalfWidth) +
                        " m everywhere (the boundaries lie on the centre line?)");
  return measured;
}

// A stretch of a road between junction cuts (the whole road when it has none).
struct RoadPiece {
  double begin = 0, end = 0;  // stations along the centre line
  std::string junction;       // the junction it crosses; empty outside junctions
};

// The legs of `sites` on road `road`.
std::vector<outline::JunctionLeg> legs_of(std::size_t road, const std::vector<JunctionSite>& sites,
                                          std::vector<std::string>* junctions = nullptr) {
  std::vector<outline::JunctionLeg> legs;
  for (const JunctionSite& site : sites)
    for (const outline::JunctionLeg& leg : site.legs)
      if (leg.road == road) {
        legs.push_back(leg);
        if (junctions) junctions->push_back(site.id);
      }
  return legs;
}

// The road's samples with its junctions' cuts among them, and its kept pieces in point order: a
// junction's stretch of a road crossing it is a piece of that junction, one of a road ending (or
// starting) in it is dropped.
std::vector<RoadPiece> cut_road(MeasuredRoad& road, std::size_t index,
                                const std::vector<JunctionSite>& sites) {
  std::vector<std::string> junctions;
  const std::vector<outline::JunctionLeg> legs = legs_of(index, sites, &junctions);
  const double length = road.shape.centre.length();
  std::vector<double> cuts{0, length};
  for (const outline::JunctionLeg& leg : legs)
    for (double station : {leg.begin, leg.end})
      if (station > kSameStation && station < length - kSameStation) cuts.push_back(station);
  std::sort(cuts.begin(), cuts.end());
  road.shape.samples = outline::with_stations(road.shape.samples, road.shape.centre, cuts);
  road.shape.right_widths = outline::half_widths(road.shape.samples, road.given->right_boundary);
  road.shape.left_widths = outline::half_widths(road.shape.samples, road.given->left_boundary);
  std::vector<RoadPiece> pieces;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i + 1] - cuts[i] < kSameStation) continue;
    const double middle = (cuts[i] + cuts[i + 1]) / 2;
    RoadPiece piece{cuts[i], cuts[i + 1], ""};
    bool dropped = false;
    for (std::size_t l = 0; l < legs.size(); ++l)
      if (legs[l].begin <= middle && middle <= legs[l].end) {
        dropped = legs[l].kind != outline::LegKind::through;
        piece.junction = junctions[l];
      }
    if (!dropped) pieces.push_back(std::move(piece));
  }
  return pieces;
}

// Lane ids: <road>_f<k> on a road without junctions; with them each kept piece's lanes get
// _<number>, numbered 1, 2, ... in the lane's driving direction, and <road>_f<k> names the chain.
struct LaneNames {
  std::string road;
  std::size_t pieces = 1;
  bool cut = false;

  std::string chain(HalfSide side, int k) const {
    return road + (side == HalfSide::right ? "_f" : "_b") + std::to_string(k);
  }
  std::string operator()(HalfSide side, int k, std::size_t piece) const {
    if (!cut) return chain(side, k);
    const std::size_t number = side == HalfSide::right ? piece + 1 : pieces - piece;
    return chain(side, k) + "_" + std::to_string(number);
  }
};

// The lanes of one half of one piece with their ids, neighbours (none inside a junction) and
// boundary types.
void add_half(MapDescription& map, const MeasuredRoad& road, const RoadPiece& piece,
              std::size_t piece_index, const LaneNames& names, HalfSide side) {
  const std::vector<CentreSample>& samples = road.shape.samples;
  const std::size_t first = outline::sample_at(samples, piece.begin);
  const std::size_t count = outline::sample_at(samples, piece.end) - first + 1;
  const int n = road.lanes(side);
  const bool opposite_lanes = road.lanes(other(side)) > 0;
  const bool free = piece.junction.empty();
  for (int k = 0; k < n; ++k) {
    LaneDescription lane =
        outline::half_lane(std::span(samples).subspan(first, count),
                           std::span(road.widths(side)).subspan(first, count), side, n, k);
    lane.id = names(side, k, piece_index);
    if (k > 0 && free) lane.left_forward_neighbours = {names(side, k - 1, piece_index)};
    if (k + 1 < n && free) lane.right_forward_neighbours = {names(side, k + 1, piece_index)};
    if (k == 0 && opposite_lanes && free)
      lane.left_reverse_neighbours = {names(other(side), 0, piece_index)};
    const BoundaryType centre = opposite_lanes ? BoundaryType::dotted_yellow : BoundaryType::curb;
    lane.left_boundary_type = k == 0 ? centre : BoundaryType::dotted_white;
    lane.right_boundary_type = k + 1 == n ? BoundaryType::curb : BoundaryType::dotted_white;
    lane.speed_limit = road.given->speed_limit;
    lane.junction = piece.junction;
    map.lanes.push_back(std::move(lane));
  }
}

// The arc length along the whole uncut lane at each sample of the road, in point order.
std::vector<double> whole_lane_stations(const MeasuredRoad& road, HalfSide side, int k) {
  const LaneDescription whole =
      outline::half_lane(road.shape.samples, road.widths(side), side, road.lanes(side), k);
  std::vector<double> arc{0};
  for (std::size_t i = 1; i < whole.centre_line.size(); ++i)
    arc.push_back(arc.back() + distance(whole.centre_line[i - 1], whole.centre_line[i]));
  if (side == HalfSide::left) std::reverse(arc.begin(), arc.end());  // in point order
  return arc;
}

// Each cut lane's chain: its pieces in driving order, each where it begins along the whole lane.
void add_chains(MapDescription& map, const MeasuredRoad& road, const std::vector<RoadPiece>& pieces,
                const LaneNames& names) {
  for (HalfSide side : {HalfSide::right, HalfSide::left})
    for (int k = 0; k < road.lanes(side); ++k) {
      const std::vector<double> arc = whole_lane_stations(road, side, k);
      LaneChainDescription chain{names.chain(side, k), {}};
      for (std::size_t j = 0; j < pieces.size(); ++j) {
        const double begins = side == HalfSide::right ? pieces[j].begin : pieces[j].end;
        chain.pieces.push_back(
            {names(side, k, j), arc[outline::sample_at(road.shape.samples, begins)]});
      }
      if (side == HalfSide::left) std::reverse(chain.pieces.begin(), chain.pieces.end());
      map.lane_chains.push_back(std::move(chain));
    }
}

// Where the road leaves a junction at `station`: after it in the point order, or before it.
outline::JunctionArm arm(const MeasuredRoad& road, const std::vector<RoadPiece>& pieces,
                         const LaneNames& names, double station, bool after) {
  const Polyline& centre = road.shape.centre;
  const double heading = centre.heading_at(station);
  outline::JunctionArm arm;
  arm.road = road.given->name;
  arm.outward = after ? MapPoint{std::cos(heading), std::sin(heading)}
                      : MapPoint{-std::cos(heading), -std::sin(heading)};
  std::size_t piece = 0;
  while (piece < pieces.size() &&
         std::abs((after ? pieces[piece].begin : pieces[piece].end) - station) > kSameStation)
    ++piece;
  SCENFUZZ_DEMAND(piece < pieces.size());
  const HalfSide in = after ? HalfSide::left : HalfSide::right;
  for (int k = 0; k < road.lanes(in); ++k) arm.in_lanes.push_back(names(in, k, piece));
  for (int k = 0; k < road.lanes(other(in)); ++k)
    arm.out_lanes.push_back(names(other(in), k, piece));
  const std::size_t sample = outline::sample_at(road.shape.samples, station);
  const CentreSample& at = road.shape.samples[sample];
  const double left = road.shape.left_widths[sample], right = road.shape.right_widths[sample];
  arm.edges = {
      MapPoint{at.point.x + left * at.left_normal.x, at.point.y + left * at.left_normal.y},
      MapPoint{at.point.x - right * at.left_normal.x, at.point.y - right * at.left_normal.y}};
  return arm;
}

// The heading of a line's first (or last) segment of positive length; none when it has none.
std::optional<double> end_heading(const std::vector<MapPoint>& points, bool at_start) {
  const std::size_t n = points.size();
  for (std::size_t step = 1; step < n; ++step) {
    const MapPoint a = at_start ? points[0] : points[n - 1 - step];
    const MapPoint b = at_start ? points[step] : points[n - 1];
    if (distance(a, b) > 1e-6) return std::atan2(b.y - a.y, b.x - a.x);
  }
  return std::nullopt;
}

bool continues_into(const LaneDescription& from, const LaneDescription& to) {
  if (distance(from.centre_line.back(), to.centre_line.front()) > kConnectionReach) return false;
  const std::optional<double> out = end_heading(from.centre_line, false);
  const std::optional<double> in = end_heading(to.centre_line, true);
  return out && in && std::abs(angle_difference(*in, *out)) < kConnectionAngle;
}

void connect_lanes(std::vector<LaneDescription>& lanes) {
  for (LaneDescription& from : lanes)
    for (LaneDescription& to : lanes)
      if (&from != &to && continues_into(from, to)) {
        from.successors.push_back(to.id);
        to.predecessors.push_back(from.id);
      }
}

void check_names(const std::string& map, const std::vector<RoadOutlineGeometry>& roads) {
  if (roads.empty()) throw MapError("map '" + map + "': the road network has no roads");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < roads.size(); ++i) {
    if (roads[i].name.empty())
      throw MapError("map '" + map + "': road " + std::to_string(i + 1) +
                     " of the road network has no name");
    if (!seen.insert(roads[i].name).second) fail(roads[i].name, "two roads have this name");
  }
}

// A junction's arms: each road's before the junction unless it starts there, after it unless
// it ends there.
std::vector<outline::JunctionArm> arms_of(const JunctionSite& site,
                                          const std::vector<MeasuredRoad>& roads,
                                          const std::vector<std::vector<RoadPiece>>& pieces,
                                          const std::vector<LaneNames>& names) {
  std::vector<outline::JunctionArm> arms;
  for (const outline::JunctionLeg& leg : site.legs) {
    const std::size_t r = leg.road;
    if (leg.kind != outline::LegKind::starts)
      arms.push_back(arm(roads[r], pieces[r], names[r], leg.begin, false));
    if (leg.kind != outline::LegKind::ends)
      arms.push_back(arm(roads[r], pieces[r], names[r], leg.end, true));
  }
  return arms;
}

// The site each signal controls, by the signals' order: the one whose meeting point is nearest.
std::vector<std::size_t> signalled_sites(const std::vector<OutlineSignal>& signals,
                                         const std::vector<JunctionSite>& sites) {
  std::vector<std::size_t> chosen;
  for (const OutlineSignal& signal : signals) {
    if (sites.empty())
      throw MapError("traffic light '" + signal.name +
                     "': the road network has no junction for it to control (roads that cross "
                     "or meet make one)");
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < sites.size(); ++i)
      if (distance(sites[i].centre, signal.at) < distance(sites[nearest].centre, signal.at))
        nearest = i;
    for (std::size_t k = 0; k < chosen.size(); ++k)
      if (chosen[k] == nearest)
        throw MapError("traffic lights '" + signals[k].name + "' and '" + signal.name +
                       "' are both nearest " + sites[nearest].id +
                       ": one light controls a junction");
    chosen.push_back(nearest);
  }
  return chosen;
}

// The road of `arms` whose lights show the signal's colour at the start: the signal's own road
// when the junction is on it, else the junction's first.
const std::string& signal_road(const OutlineSignal& signal,
                               const std::vector<outline::JunctionArm>& arms) {
  for (const outline::JunctionArm& arm : arms)
    if (arm.road == signal.road) return arm.road;
  return arms.front().road;
}

}  // namespace

MapDescription describe_outline_map(std::string name, const std::vector<RoadOutlineGeometry>& roads,
                                    const std::vector<OutlineSignal>& signals) {
  check_names(name, roads);
  MapDescription map;
  map.name = std::move(name);
  map.source = kSource;
  map.default_lane_width = outline::kNominalLaneWidth;
  std::vector<MeasuredRoad> measured;
  std::vector<outline::RoadShape> shapes;
  for (const RoadOutlineGeometry& road : roads) {
    measured.push_back(measure(road));
    shapes.push_back(measured.back().shape);
  }
  const std::vector<JunctionSite> sites = outline::find_junction_sites(shapes);
  std::vector<std::vector<RoadPiece>> pieces;
  std::vector<LaneNames> names;
  for (std::size_t r = 0; r < measured.size(); ++r) {
    pieces.push_back(cut_road(measured[r], r, sites));
    names.push_back({roads[r].name, pieces.back().size(), !legs_of(r, sites).empty()});
    for (std::size_t j = 0; j < pieces[r].size(); ++j)
      for (HalfSide side : {HalfSide::right, HalfSide::left})
        add_half(map, measured[r], pieces[r][j], j, names[r], side);
    if (names[r].cut) add_chains(map, measured[r], pieces[r], names[r]);
  }
  const std::vector<std::size_t> signalled = signalled_sites(signals, sites);
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const std::vector<outline::JunctionArm> arms = arms_of(sites[i], measured, pieces, names);
    outline::add_junction(map, sites[i].id, arms);
    for (std::size_t k = 0; k < signals.size(); ++k)
      if (signalled[k] == i)
        outline::add_signals(map, signals[k].name, signal_road(signals[k], arms), signals[k].colour,
                             arms);
  }
  connect_lanes(map.lanes);
  return map;
}

}  // namespace scenfuzz
