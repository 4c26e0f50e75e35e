// Accident reconstruction scored on a trace. Every condition of a described collision (the pair
// touched, with the named parts, in order, near the place) is a distance in metres that is > 0
// when unmet; a collision's robustness is the largest unmet one plus a margin, or, when all are
// met, minus the margin and the smallest slack. Geometry is the footprints' (oriented rectangles
// and discs, physics/collision/footprint.hpp), the same the simulation detects contacts on.
#include "oracle/collision_reconstruction.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "lang/demand.hpp"
#include "lang/value.hpp"
#include "physics/trace/trace_footprint.hpp"

namespace scenfuzz {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr BodySide kAllSides[] = {BodySide::front, BodySide::rear, BodySide::left, BodySide::right};

// ---- geometry --------------------------------------------------------------------------------

struct Segment {
  MapPoint a, b;
};

// A point given in the body's frame (x along its heading, y to its left), in the map frame.
MapPoint from_body_frame(const Footprint& body, double x, double y) {
  const double c = std::cos(body.heading), s = std::sin(body.heading);
  return {body.centre.x + x * c - y * s, body.centre.y + x * s + y * c};
}

// The edge of a rectangle on `side`.
Segment side_segment(const Footprint& box, BodySide side) {
  const double l = box.half_length, w = box.half_width;
  switch (side) {
    case BodySide::front: return {from_body_frame(box, l, -w), from_body_frame(box, l, w)};
    case BodySide::rear: return {from_body_frame(box, -l, -w), from_body_frame(box, -l, w)};
    case BodySide::left: return {from_body_frame(box, -l, w), from_body_frame(box, l, w)};
    case BodySide::right: return {from_body_frame(box, -l, -w), from_body_frame(box, l, -w)};
  }
  return {};
}

double point_segment_distance(MapPoint p, Segment s) {
  const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  const double length_squared = dx * dx + dy * dy;
  double t = length_squared > 0 ? ((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / length_squared : 0;
  t = std::clamp(t, 0.0, 1.0);
  return distance(p, {s.a.x + t * dx, s.a.y + t * dy});
}

// Twice the signed area of (a, b, c): positive when c lies left of a->b.
double cross(MapPoint a, MapPoint b, MapPoint c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool segments_cross(Segment s, Segment t) {
  const double d1 = cross(s.a, s.b, t.a), d2 = cross(s.a, s.b, t.b);
  const double d3 = cross(t.a, t.b, s.a), d4 = cross(t.a, t.b, s.b);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

// Between two segments: 0 when they cross, else the nearest endpoint to the other segment.
double segment_distance(Segment s, Segment t) {
  if (segments_cross(s, t)) return 0;
  return std::min({point_segment_distance(s.a, t), point_segment_distance(s.b, t),
                   point_segment_distance(t.a, s), point_segment_distance(t.b, s)});
}

bool inside_box(const Footprint& box, MapPoint p) {
  const double c = std::cos(box.heading), s = std::sin(box.heading);
  const double dx = p.x - box.centre.x, dy = p.y - box.centre.y;
  return std::abs(dx * c + dy * s) <= box.half_length &&
         std::abs(-dx * s + dy * c) <= box.half_width;
}

// From a segment to a whole body (rectangle or disc), 0 when they touch or overlap.
double segment_body_distance(Segment s, const Footprint& body) {
  if (body.round) return std::max(point_segment_distance(body.centre, s) - body.half_length, 0.0);
  if (inside_box(body, s.a)) return 0;
  double nearest = kInfinity;
  for (BodySide side : kAllSides)
    nearest = std::min(nearest, segment_distance(s, side_segment(body, side)));
  return nearest;
}

// From a point to the quarter of a disc's rim that side_of calls `side` (the quarter centred on
// the side's direction), so that a contact's distance to a named side of a round body is
// measured along the rim's quarters exactly as the trace's sides were assigned.
double point_arc_distance(const Footprint& disc, BodySide side, MapPoint p) {
  constexpr double kQuarter = std::numbers::pi / 4;
  const double centre_bearing = side == BodySide::front  ? 0
                                : side == BodySide::left ? std::numbers::pi / 2
                                : side == BodySide::rear ? std::numbers::pi
                                                         : -std::numbers::pi / 2;
  const double bearing = std::atan2(p.y - disc.centre.y, p.x - disc.centre.x) - disc.heading;
  const double offset = std::clamp(angle_difference(bearing, centre_bearing), -kQuarter, kQuarter);
  const double angle = disc.heading + centre_bearing + offset;
  const double r = disc.half_length;
  return distance(p, {disc.centre.x + r * std::cos(angle), disc.centre.y + r * std::sin(angle)});
}

// From a point to one side of a body: an edge of a rectangle, a quarter of a disc's rim.
double point_side_distance(const Footprint& body, BodySide side, MapPoint p) {
  if (body.round) return point_arc_distance(body, side, p);
  return point_segment_distance(p, side_segment(body, side));
}

// How far `p` (a contact on `side`) is from every other side: how firmly it is on `side`.
double distance_to_other_sides(const Footprint& body, BodySide side, MapPoint p) {
  double nearest = kInfinity;
  for (BodySide other : kAllSides)
    if (other != side) nearest = std::min(nearest, point_side_distance(body, other, p));
  return nearest;
}

// A named part of a body at one sample: an edge of a rectangle, or the whole body (a part
// `unknown`, and any part of a disc: the closest approach only guides the search while the pair
// has not touched, and a disc's quarters differ from the whole by less than its radius).
struct PartShape {
  Footprint body;
  std::optional<Segment> edge;
};

PartShape part_at(const Trace& trace, ActorId actor, std::size_t sample,
                  std::optional<BodySide> side) {
  PartShape part{footprint_at(trace, actor, sample), std::nullopt};
  if (side && !part.body.round) part.edge = side_segment(part.body, *side);
  return part;
}

MapPoint midpoint(Segment s) { return {(s.a.x + s.b.x) / 2, (s.a.y + s.b.y) / 2}; }

// Between two named faces: how far their middles are apart, never less than their gap. Faces
// nearly touching at their corners (a front corner grazing a rear corner) are not nearly the
// described contact, and a search that read the gap alone stalled there; the middles come together
// only as the faces line up, alongside or head on, as they do in the contact described.
double face_distance(Segment p, Segment q) {
  const MapPoint a = midpoint(p), b = midpoint(q);
  return std::hypot(a.x - b.x, a.y - b.y);
}

double part_distance(const PartShape& p, const PartShape& q) {
  if (p.edge && q.edge) return face_distance(*p.edge, *q.edge);
  if (p.edge) return segment_body_distance(*p.edge, q.body);
  if (q.edge) return segment_body_distance(*q.edge, p.body);
  return std::max(signed_distance(p.body, q.body), 0.0);
}

// ---- the trace -------------------------------------------------------------------------------

ActorId actor_named(const Trace& trace, const std::string& name) {
  const std::optional<ActorId> id = trace.find_actor(name);
  if (!id)
    throw std::invalid_argument("the accident description names '" + name +
                                "', which is no actor of the trace");
  return *id;
}

// The pair's first contact, in either order of ids; nullptr when they never touched.
const Collision* contact_between(const Trace& trace, ActorId a, ActorId b) {
  for (const Collision& c : trace.collisions)
    if ((c.first == a && c.second == b) || (c.first == b && c.second == a)) return &c;
  return nullptr;
}

// The sample nearest to `time`.
std::size_t sample_at(const Trace& trace, double time) {
  SCENFUZZ_DEMAND(trace.sample_count() > 0);
  const auto after = std::lower_bound(trace.time.begin(), trace.time.end(), time);
  if (after == trace.time.end()) return trace.sample_count() - 1;
  const auto i = static_cast<std::size_t>(after - trace.time.begin());
  return i > 0 && time - trace.time[i - 1] < *after - time ? i - 1 : i;
}

// The smallest distance between the two named parts over the samples both are on the map.
double closest_approach(const Trace& trace, ActorId striker, std::optional<BodySide> striker_side,
                        ActorId victim, std::optional<BodySide> victim_side) {
  double nearest = kInfinity;
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    if (!present_at(trace.actors[striker], i) || !present_at(trace.actors[victim], i)) continue;
    nearest = std::min(nearest, part_distance(part_at(trace, striker, i, striker_side),
                                              part_at(trace, victim, i, victim_side)));
  }
  return nearest;
}

// The described place in the map frame, or nullopt when none is given.
std::optional<MapPoint> described_place(const Trace& trace, const ExpectedCollision& expected,
                                        std::span<const double> parameter_values) {
  if (!expected.position) return std::nullopt;
  const Position& place = *expected.position;
  if (place.kind != PositionKind::coordinate || place.frame == Frame::wgs84)
    throw std::invalid_argument(
        "the place of a described collision must be an ENU or IMU "
        "coordinate");
  const double x = evaluate(place.x, parameter_values), y = evaluate(place.y, parameter_values);
  if (place.frame == Frame::enu) return MapPoint{x, y};
  if (trace.actors.empty() || trace.sample_count() == 0)
    throw std::invalid_argument("an IMU place needs the ego's initial pose");
  // IMU, as physics/map/scenario_position.cpp places it: x to the ego's right, y forward.
  const TraceActor& ego = trace.actors[kEgo];
  const double fx = std::cos(ego.heading[0]), fy = std::sin(ego.heading[0]);
  return MapPoint{ego.x[0] + y * fx + x * fy, ego.y[0] + y * fy - x * fx};
}

// ---- wording ---------------------------------------------------------------------------------

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  std::string result = text;
  while (result.back() == '0') result.pop_back();
  if (result.back() == '.') result.pop_back();
  return result == "-0" ? "0" : result;
}

std::string part_words(std::optional<BodySide> side) {
  return side ? body_side_words(*side) : "any part";
}

// "its front", "car1's rear, not its left side": the side touched, and the named one if other.
std::string seen_side_words(const std::string& owner, BodySide seen,
                            std::optional<BodySide> named) {
  std::string words = owner + " " + body_side_words(seen);
  if (named && *named != seen) words += ", not its " + body_side_words(*named);
  return words;
}

// ---- one described collision -----------------------------------------------------------------

// Who is who in one described collision.
struct NamedPair {
  const ExpectedCollision* expected = nullptr;
  ActorId striker = 0, victim = 0;
  std::optional<BodySide> striker_part, victim_part;
};

CollisionCheck missed(const Trace& trace, const NamedPair& pair) {
  CollisionCheck check;
  check.closest_approach =
      closest_approach(trace, pair.striker, pair.striker_part, pair.victim, pair.victim_part);
  check.robustness = check.closest_approach + kReconstructionMargin;
  const ExpectedCollision& e = *pair.expected;
  check.problem = e.striker + " never touched " + e.victim;
  if (std::isfinite(check.closest_approach))
    check.problem += " (closest approach of " + e.striker + "'s " + part_words(pair.striker_part) +
                     " to " + e.victim + "'s " + part_words(pair.victim_part) + ": " +
                     number(check.closest_approach) + " m)";
  else
    check.problem += " (they were never on the map together)";
  return check;
}

// The conditions of a contact: how far each unmet one misses (m, >= 0) with its wording, and how
// much room each met one has (m, >= 0).
struct Conditions {
  double worst_miss = -1;  // < 0: none unmet
  std::vector<std::string> misses;
  double least_slack = kInfinity;

  void miss(double amount, std::string words) {
    worst_miss = std::max(worst_miss, amount);
    misses.push_back(std::move(words));
  }
  void slack(double room) { least_slack = std::min(least_slack, room); }
};

// How far the contact is from the named side of one body; nullopt when the part is unknown or
// the contact is on it (then how firmly it is on it is recorded as slack).
std::optional<double> part_miss(Conditions& conditions, const Footprint& body,
                                std::optional<BodySide> named, BodySide seen, MapPoint contact) {
  if (!named) return std::nullopt;
  if (*named != seen) return point_side_distance(body, *named, contact);
  conditions.slack(distance_to_other_sides(body, seen, contact));
  return std::nullopt;
}

// Both named parts against the sides touched, on the bodies where they were at the contact.
void check_parts(Conditions& conditions, const Trace& trace, const NamedPair& pair,
                 const CollisionCheck& check) {
  const std::size_t sample = sample_at(trace, check.time);
  const std::optional<double> striker_miss =
      part_miss(conditions, footprint_at(trace, pair.striker, sample), pair.striker_part,
                check.striker_side, check.contact);
  const std::optional<double> victim_miss =
      part_miss(conditions, footprint_at(trace, pair.victim, sample), pair.victim_part,
                check.victim_side, check.contact);
  if (!striker_miss && !victim_miss) return;
  // "with its rear, not its front, on car1's left side": the aside closed by a comma.
  const std::string striker_words =
      seen_side_words("its", check.striker_side, pair.striker_part) + (striker_miss ? "," : "");
  conditions.miss(
      std::max(striker_miss.value_or(0), victim_miss.value_or(0)),
      "with " + striker_words + " on " +
          seen_side_words(pair.expected->victim + "'s", check.victim_side, pair.victim_part));
}

// Not before the latest earlier described collision that happened.
void check_order(Conditions& conditions, double time, std::optional<double> previous) {
  if (!previous) return;
  if (time >= *previous) return conditions.slack((time - *previous) * kOrderSpeed);
  conditions.miss((*previous - time) * kOrderSpeed,
                  "at " + number(time) + " s, before the collision described before it (at " +
                      number(*previous) + " s)");
}

void check_place(Conditions& conditions, MapPoint contact, std::optional<MapPoint> place) {
  if (!place) return;
  const double off = distance(contact, *place);
  if (off < kPlaceTolerance) return conditions.slack(kPlaceTolerance - off);
  conditions.miss(off - kPlaceTolerance, number(off) + " m from the described place (" +
                                             number(place->x) + ", " + number(place->y) +
                                             "), beyond the " + number(kPlaceTolerance) +
                                             " m tolerance");
}

std::string joined(const std::vector<std::string>& clauses) {
  std::string text;
  for (std::size_t i = 0; i < clauses.size(); ++i) text += (i == 0 ? " " : ", and ") + clauses[i];
  return text;
}

CollisionCheck touched(const Trace& trace, const NamedPair& pair, const Collision& contact,
                       std::optional<MapPoint> place, std::optional<double> previous) {
  CollisionCheck check;
  check.happened = true;
  check.time = contact.time;
  check.contact = contact.point;
  const bool striker_first = contact.first == pair.striker;
  check.striker_side = striker_first ? contact.first_side : contact.second_side;
  check.victim_side = striker_first ? contact.second_side : contact.first_side;
  Conditions conditions;
  check_parts(conditions, trace, pair, check);
  check_order(conditions, check.time, previous);
  check_place(conditions, check.contact, place);
  check.satisfied = conditions.worst_miss < 0;
  if (check.satisfied) {
    const double slack = std::isfinite(conditions.least_slack) ? conditions.least_slack : 0;
    check.robustness = -(kReconstructionMargin + slack);
    return check;
  }
  check.robustness = conditions.worst_miss + kReconstructionMargin;
  check.problem =
      pair.expected->striker + " hit " + pair.expected->victim + joined(conditions.misses);
  return check;
}

NamedPair named_pair(const Trace& trace, const ExpectedCollision& expected) {
  NamedPair pair{&expected, actor_named(trace, expected.striker),
                 actor_named(trace, expected.victim), body_side_of(expected.striker_part),
                 body_side_of(expected.victim_part)};
  if (pair.striker == pair.victim)
    throw std::invalid_argument("a described collision of '" + expected.striker + "' with itself");
  return pair;
}

}  // namespace

std::optional<BodySide> body_side_of(VehiclePart part) {
  switch (part) {
    case VehiclePart::front: return BodySide::front;
    case VehiclePart::rear: return BodySide::rear;
    case VehiclePart::left_side: return BodySide::left;
    case VehiclePart::right_side: return BodySide::right;
    case VehiclePart::unknown: return std::nullopt;
  }
  return std::nullopt;
}

std::string body_side_words(BodySide side) {
  switch (side) {
    case BodySide::front: return "front";
    case BodySide::rear: return "rear";
    case BodySide::left: return "left side";
    case BodySide::right: return "right side";
  }
  return "side";
}

std::string vehicle_part_words(VehiclePart part) { return part_words(body_side_of(part)); }

namespace {

bool described(const std::vector<NamedPair>& pairs, const Collision& collision) {
  for (const NamedPair& pair : pairs)
    if ((collision.first == pair.striker && collision.second == pair.victim) ||
        (collision.first == pair.victim && collision.second == pair.striker))
      return true;
  return false;
}

// The collisions the description does not list, up to `until` (s).
std::vector<UndescribedCollision> undescribed_collisions(const Trace& trace,
                                                         const std::vector<NamedPair>& pairs,
                                                         double until) {
  std::vector<UndescribedCollision> found;
  for (const Collision& collision : trace.collisions) {
    if (collision.time > until || described(pairs, collision)) continue;
    found.push_back({trace.actors[collision.first].name, trace.actors[collision.second].name,
                     collision.time,
                     kReconstructionMargin + (until - collision.time) * kOrderSpeed});
  }
  return found;
}

}  // namespace

ReconstructionScore score_reconstruction(const Trace& trace,
                                         const std::vector<ExpectedCollision>& expected,
                                         std::span<const double> parameter_values) {
  ReconstructionScore score{-kInfinity, {}, {}};
  std::optional<double> latest;  // the latest time of the earlier collisions that happened
  std::vector<NamedPair> pairs;
  bool all_happened = true;
  for (const ExpectedCollision& e : expected) {
    const NamedPair pair = named_pair(trace, e);
    pairs.push_back(pair);
    const std::optional<MapPoint> place = described_place(trace, e, parameter_values);
    const Collision* contact = contact_between(trace, pair.striker, pair.victim);
    CollisionCheck check =
        contact ? touched(trace, pair, *contact, place, latest) : missed(trace, pair);
    if (check.happened) latest = std::max(latest.value_or(check.time), check.time);
    all_happened = all_happened && check.happened;
    score.robustness = std::max(score.robustness, check.robustness);
    score.collisions.push_back(std::move(check));
  }
  const double end = trace.time.empty() ? 0 : trace.time.back();
  score.undescribed = undescribed_collisions(trace, pairs, all_happened && latest ? *latest : end);
  for (const UndescribedCollision& extra : score.undescribed)
    score.robustness = std::max(score.robustness, extra.robustness);
  return score;
}

}  // namespace scenfuzz
