// The regions' rules. Margins leave room around bodies at the edges for their labels.
#include "physics/trace/picture_regions.hpp"

#include <algorithm>
#include <cmath>

namespace scenfuzz {
namespace {

constexpr double main_min_margin = 8;          // m
constexpr double main_margin_fraction = 0.06;  // of the longer side
constexpr double nearby_other = 60;            // m from the ego at the event
constexpr double lead_up = 5;                  // s before the event whose nearby bodies count
constexpr double inset_min_side = 24;          // m
constexpr double inset_margin = 4;             // m
constexpr double inset_other_gap = 30;         // m: a farther other party is left out of the inset

double body_radius(const TraceActor& actor) { return std::hypot(actor.length, actor.width) / 2; }

void include_body(MapBounds& bounds, const TraceActor& actor, MapPoint centre) {
  const double r = body_radius(actor);
  bounds.include({centre.x - r, centre.y - r});
  bounds.include({centre.x + r, centre.y + r});
}

MapPoint position(const TraceActor& actor, std::size_t i) { return {actor.x[i], actor.y[i]}; }

void grow(MapBounds& bounds, double margin) {
  bounds.include({bounds.min.x - margin, bounds.min.y - margin});
  bounds.include({bounds.max.x + margin, bounds.max.y + margin});
}

// At least `side` metres each way, about its centre.
void at_least(MapBounds& bounds, double side) {
  const MapPoint centre{(bounds.min.x + bounds.max.x) / 2, (bounds.min.y + bounds.max.y) / 2};
  bounds.include({centre.x - side / 2, centre.y - side / 2});
  bounds.include({centre.x + side / 2, centre.y + side / 2});
}

}  // namespace

MapPoint velocity_at(const TraceActor& actor, std::size_t i) {
  if (i >= actor.speed.size() || i >= actor.heading.size() || !std::isfinite(actor.speed[i]) ||
      !std::isfinite(actor.heading[i]))
    return {0, 0};
  const double v = longitudinal_velocity_at(actor.speed, actor.reversing, i);
  return {v * std::cos(actor.heading[i]), v * std::sin(actor.heading[i])};
}

MapBounds with_bounded_aspect(const MapBounds& bounds, double max_aspect) {
  if (bounds.empty()) return bounds;
  MapBounds result = bounds;
  const double width = bounds.max.x - bounds.min.x, height = bounds.max.y - bounds.min.y;
  const double cx = (bounds.min.x + bounds.max.x) / 2, cy = (bounds.min.y + bounds.max.y) / 2;
  if (width > max_aspect * height) {
    const double half = width / max_aspect / 2;
    result.include({cx, cy - half});
    result.include({cx, cy + half});
  } else if (height > max_aspect * width) {
    const double half = height / max_aspect / 2;
    result.include({cx - half, cy});
    result.include({cx + half, cy});
  }
  return result;
}

MapBounds inset_region(const Trace& trace, const TraceMoment& moment) {
  MapBounds bounds;
  bounds.include(moment.point);
  const double step_back = std::max(trace.dt, 1e-6);
  // The other party when it was hit or near enough to matter; else the inset would not zoom.
  const bool other_near =
      moment.other &&
      (moment.collision || gap_to_ego(trace, *moment.other, moment.sample) <= inset_other_gap);
  for (const std::optional<ActorId> id :
       {std::optional<ActorId>(kEgo), other_near ? moment.other : std::nullopt}) {
    if (!id) continue;
    const TraceActor& actor = trace.actors[*id];
    for (int second = 0; second <= static_cast<int>(kInsetLookBack); ++second) {
      const double back = second / step_back;
      if (back > static_cast<double>(moment.sample) + 1e-9) break;
      const std::size_t i = moment.sample - static_cast<std::size_t>(std::lround(back));
      if (!drawn_at(trace, *id, i)) continue;
      include_body(bounds, actor, position(actor, i));
      if (second == 0) {
        const MapPoint v = velocity_at(actor, i);
        bounds.include({actor.x[i] + v.x, actor.y[i] + v.y});
      }
    }
  }
  at_least(bounds, inset_min_side);
  grow(bounds, inset_margin);
  return with_bounded_aspect(bounds, kInsetMaxAspect);
}

MapBounds main_region(const RoadMap& map, const Trace& trace,
                      const std::optional<TraceMoment>& moment,
                      const std::optional<MapBounds>& inset) {
  MapBounds bounds;
  double largest_body = 0;
  if (moment) {
    const TraceActor& ego = trace.actors[kEgo];
    for (std::size_t i = 0; i < ego.x.size(); ++i)
      if (drawn_at(trace, kEgo, i)) bounds.include(position(ego, i));
    largest_body = body_radius(ego);
    if (trace.ego_target) bounds.include(*trace.ego_target);
    if (inset) {
      bounds.include(inset->min);
      bounds.include(inset->max);
    }
    for (const Collision& collision : trace.collisions)
      if ((collision.first == kEgo || collision.second == kEgo) &&
          std::isfinite(collision.point.x) && std::isfinite(collision.point.y))
        bounds.include(collision.point);
    const MapPoint ego_then = position(ego, moment->sample);
    const std::size_t first =
        moment->sample -
        std::min(moment->sample,
                 static_cast<std::size_t>(std::lround(lead_up / std::max(trace.dt, 1e-6))));
    for (std::size_t id = 1; id < trace.actors.size(); ++id)
      for (std::size_t i = first; i <= moment->sample; ++i)
        if (drawn_at(trace, id, i) &&
            distance(position(trace.actors[id], i), ego_then) <= nearby_other) {
          bounds.include(position(trace.actors[id], i));
          largest_body = std::max(largest_body, body_radius(trace.actors[id]));
        }
  } else {
    for (std::size_t id = 0; id < trace.actors.size(); ++id)
      for (std::size_t i = 0; i < trace.actors[id].x.size(); ++i)
        if (drawn_at(trace, id, i)) {
          bounds.include(position(trace.actors[id], i));
          largest_body = std::max(largest_body, body_radius(trace.actors[id]));
        }
  }
  if (bounds.empty()) bounds = map.bounds();
  if (bounds.empty()) bounds.include({0, 0});
  const double extent = std::max(bounds.max.x - bounds.min.x, bounds.max.y - bounds.min.y);
  grow(bounds, std::max(main_min_margin, main_margin_fraction * extent) + largest_body);
  return with_bounded_aspect(bounds, kMainMaxAspect);
}

}  // namespace scenfuzz
