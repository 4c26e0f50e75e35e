// Gaps from bodies projected on the frame's axes: a box turned by a against the frame reaches
// L/2 |cos a| + W/2 |sin a| along it; a round body its radius.
#include "oracle/pair_geometry.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include "physics/map/lane_queries.hpp"

namespace scenfuzz {

namespace {

// Beyond this angle to its lane an actor is not following it (turning across, reversing).
constexpr double kFollowsLane = std::numbers::pi / 4;

struct Extent {
  double along = 0;
  double across = 0;
};

Extent projected_extent(const TraceActor& actor, double heading, double frame) {
  if (actor.shape != BodyShape::box) return {actor.length / 2, actor.length / 2};
  const double a = heading - frame;
  const double c = std::abs(std::cos(a));
  const double s = std::abs(std::sin(a));
  return {actor.length / 2 * c + actor.width / 2 * s, actor.length / 2 * s + actor.width / 2 * c};
}

// The direction of the lane the actor follows at `sample`, or nullopt.
std::optional<double> followed_lane_heading(const Trace& trace, const RoadMap& map, ActorId id,
                                            std::size_t sample) {
  const TraceActor& actor = trace.actors[id];
  if (actor.lane[sample] < 0) return std::nullopt;
  const double lane =
      lane_heading_at(map, static_cast<LaneIndex>(actor.lane[sample]), actor.s[sample]);
  if (std::abs(wrap_angle(actor.heading[sample] - lane)) > kFollowsLane) return std::nullopt;
  return lane;
}

struct Velocity {
  double along = 0;
  double lateral = 0;
};

// Along the frame; sideways against the actor's own lane (or the frame, off any lane).
Velocity velocity(const Trace& trace, const RoadMap& map, ActorId id, std::size_t sample,
                  double frame) {
  const TraceActor& actor = trace.actors[id];
  const double v = longitudinal_velocity_at(actor.speed, actor.reversing, sample);
  const double h = actor.heading[sample];
  const double lateral_frame = followed_lane_heading(trace, map, id, sample).value_or(frame);
  return {v * std::cos(h - frame), v * std::sin(h - lateral_frame)};
}

}  // namespace

double wrap_angle(double a) {
  a = std::remainder(a, 2 * std::numbers::pi);
  return a <= -std::numbers::pi ? a + 2 * std::numbers::pi : a;
}

double pair_frame_heading(const Trace& trace, const RoadMap& map, ActorId reference,
                          std::size_t sample) {
  return followed_lane_heading(trace, map, reference, sample)
      .value_or(trace.actors[reference].heading[sample]);
}

namespace {

// The other's centre in the frame: ahead (x) and to the left (y).
void frame_offset(const TraceActor& r, const TraceActor& o, std::size_t sample, double frame,
                  double& dx, double& dy) {
  const double c = std::cos(frame);
  const double s = std::sin(frame);
  const double ex = o.x[sample] - r.x[sample];
  const double ey = o.y[sample] - r.y[sample];
  dx = ex * c + ey * s;
  dy = -ex * s + ey * c;
}

BodyGaps gaps_at(const TraceActor& r, const TraceActor& o, std::size_t sample, double frame,
                 double dx, double dy) {
  const Extent re = projected_extent(r, r.heading[sample], frame);
  const Extent oe = projected_extent(o, o.heading[sample], frame);
  return {std::abs(dx) - re.along - oe.along, std::abs(dy) - re.across - oe.across};
}

}  // namespace

BodyGaps body_gaps(const Trace& trace, ActorId reference, ActorId other, std::size_t sample,
                   double frame_heading) {
  const TraceActor& r = trace.actors[reference];
  const TraceActor& o = trace.actors[other];
  double dx = 0, dy = 0;
  frame_offset(r, o, sample, frame_heading, dx, dy);
  return gaps_at(r, o, sample, frame_heading, dx, dy);
}

PairGeometry pair_geometry(const Trace& trace, const RoadMap& map, ActorId reference, ActorId other,
                           std::size_t sample) {
  const TraceActor& r = trace.actors[reference];
  const TraceActor& o = trace.actors[other];
  PairGeometry g;
  g.frame_heading = pair_frame_heading(trace, map, reference, sample);
  frame_offset(r, o, sample, g.frame_heading, g.dx, g.dy);
  const BodyGaps gaps = gaps_at(r, o, sample, g.frame_heading, g.dx, g.dy);
  g.gap_lon = gaps.lon;
  g.gap_lat = gaps.lat;
  const Velocity rv = velocity(trace, map, reference, sample, g.frame_heading);
  const Velocity ov = velocity(trace, map, other, sample, g.frame_heading);
  g.reference_lon = rv.along;
  g.reference_lat = rv.lateral;
  g.other_lon = ov.along;
  g.other_lat = ov.lateral;
  g.heading_difference = wrap_angle(o.heading[sample] - g.frame_heading);
  return g;
}

}  // namespace scenfuzz
