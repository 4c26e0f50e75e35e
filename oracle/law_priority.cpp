// The priority flags. Areas are rectangles in the ego's frame, measured from the middle of its
// rear bumper (LawBreaker's point R), forward along its heading and to its left; a body is in an
// area when its footprint touches it.
#include "oracle/law_priority.hpp"

#include <cmath>
#include <numbers>

#include "physics/trace/trace_footprint.hpp"

namespace scenfuzz {

namespace {

// LawBreaker's figures (m and rad).
constexpr double kVehicleTooClose = 3;       // the vehicle ahead nearer than this has priority
constexpr double kCrossingReach = 30;        // crossing traffic this near, when turning
constexpr double kOvertakingReach = 10;      // a faster car this near behind, when changing lane
constexpr double kPedestrianAheadReach = 3;  // a pedestrian ahead, going straight on
constexpr double kPedestrianSideReach = 10;  // a pedestrian on the side turned to
constexpr double kAheadLength = 200;         // the area ahead: 200 m on, 200 m to each side
constexpr double kSideSquare = 30;           // the square ahead on the side turned to
constexpr double kStripLength = 30;          // the strip behind on the side changed to
constexpr double kStripGap = 0.3;            // between the ego's side and the strip
constexpr double kStripWidth = 3;
constexpr double kSameWay = std::numbers::pi / 4;       // headings this close drive the same way
constexpr double kCrossing = 3 * std::numbers::pi / 4;  // up to this: crossing traffic

// The rectangle [back, front] x [right, left] in the ego's frame at its rear bumper's middle.
Footprint ego_area(const Footprint& ego, double back, double front, double right, double left) {
  const double forward_x = std::cos(ego.heading), forward_y = std::sin(ego.heading);
  const double along = (back + front) / 2 - ego.half_length, across = (right + left) / 2;
  return {{ego.centre.x + along * forward_x - across * forward_y,
           ego.centre.y + along * forward_y + across * forward_x},
          ego.heading,
          (front - back) / 2,
          (left - right) / 2,
          false};
}

bool touches(const Footprint& area, const Footprint& body) {
  return signed_distance(area, body) <= 0;
}

double gap(const Footprint& ego, const Footprint& body) {
  return std::max(0.0, signed_distance(ego, body));
}

}  // namespace

std::vector<double> priority_vehicle_ahead(const Trace& trace, const EgoManoeuvre& manoeuvre,
                                           std::span<const double> vehicle_ahead) {
  const TraceActor& ego_actor = trace.actors[kEgo];
  std::vector<double> values(trace.sample_count());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (vehicle_ahead[i] < kVehicleTooClose) {
      values[i] = 1;
      continue;
    }
    const double direction = manoeuvre.direction[i];
    if (direction == kForward) continue;
    const bool changing = manoeuvre.lane_changing[i] != 0;
    const Footprint ego = footprint_at(trace, kEgo, i);
    const double side = direction == kLeft ? 1 : -1;
    const double strip_near = ego.half_width + kStripGap;
    const Footprint area = changing ? ego_area(ego, -kStripLength, 0,
                                               side > 0 ? strip_near : -strip_near - kStripWidth,
                                               side > 0 ? strip_near + kStripWidth : -strip_near)
                                    : ego_area(ego, 0, kAheadLength, -kAheadLength, kAheadLength);
    for (std::size_t k = 1; k < trace.actors.size() && values[i] == 0; ++k) {
      const TraceActor& vehicle = trace.actors[k];
      if (vehicle.kind != TraceActorKind::vehicle || !present_at(vehicle, i)) continue;
      const Footprint body = footprint_at(trace, static_cast<ActorId>(k), i);
      const double heading = std::abs(angle_difference(vehicle.heading[i], ego.heading));
      const bool has_priority =
          changing ? heading < kSameWay && vehicle.speed[i] > ego_actor.speed[i] &&
                         gap(ego, body) < kOvertakingReach
                   : heading >= kSameWay && heading <= kCrossing && gap(ego, body) < kCrossingReach;
      if (has_priority && touches(area, body)) values[i] = 1;
    }
  }
  return values;
}

std::vector<double> priority_pedestrian_ahead(const Trace& trace, const EgoManoeuvre& manoeuvre) {
  std::vector<double> values(trace.sample_count());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double direction = manoeuvre.direction[i];
    const Footprint ego = footprint_at(trace, kEgo, i);
    const Footprint area = direction == kLeft ? ego_area(ego, 0, kSideSquare, 0, kSideSquare)
                           : direction == kRight
                               ? ego_area(ego, 0, kSideSquare, -kSideSquare, 0)
                               : ego_area(ego, 0, kAheadLength, -kAheadLength, kAheadLength);
    const double reach = direction == kForward ? kPedestrianAheadReach : kPedestrianSideReach;
    for (std::size_t k = 1; k < trace.actors.size() && values[i] == 0; ++k) {
      if (trace.actors[k].kind != TraceActorKind::pedestrian || !present_at(trace.actors[k], i))
        continue;
      const Footprint body = footprint_at(trace, static_cast<ActorId>(k), i);
      if (gap(ego, body) < reach && touches(area, body)) values[i] = 1;
    }
  }
  return values;
}

}  // namespace scenfuzz
