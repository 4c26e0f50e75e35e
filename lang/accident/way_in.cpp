// Where a described vehicle comes in (way_in.hpp says the rules).
#include "lang/accident/way_in.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace scenfuzz::accident {

namespace {

// The heading a sign's place asks for: the way in whose line passes nearest it.
std::optional<Direction> heading_towards(const SceneLayout& layout, PlanePoint sign) {
  std::optional<Direction> best;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& [direction, way] : layout.approaches) {
    // Only behind the entry: a sign further on is on another direction's way.
    const double along =
        (sign.x - way.entry.x) * way.direction.x + (sign.y - way.entry.y) * way.direction.y;
    const double across = std::abs((sign.x - way.entry.x) * way.direction.y -
                                   (sign.y - way.entry.y) * way.direction.x);
    const double distance = along <= 0 ? across : across + along;
    if (distance < nearest) {
      nearest = distance;
      best = direction;
    }
  }
  return best;
}

// The lane a chain of events needs to start in: a turn from the lane that has the turn's
// connector, a move to the left from the kerb lane, to the right from the lane beside it.
std::optional<int> lane_for_chain(const Vehicle& vehicle, int lanes) {
  for (const Event& event : vehicle.chain) {
    switch (event.kind.value) {
      case EventKind::turn_left:
      case EventKind::change_lane_right: return lanes - 1;
      case EventKind::turn_right:
      case EventKind::change_lane_left:
      case EventKind::overtake: return 0;
      default: break;
    }
  }
  return std::nullopt;
}

// The lane a lane change goes to, when the vehicle changes lanes.
std::optional<int> lane_changed_to(const Vehicle& vehicle, int lanes) {
  for (const Event& event : vehicle.chain) {
    if (event.kind.value == EventKind::change_lane_left) return lanes - 1;
    if (event.kind.value == EventKind::change_lane_right) return 0;
  }
  return std::nullopt;
}

const Vehicle* vehicle_named(const File& file, const std::string& name) {
  for (const Vehicle& vehicle : file.vehicles)
    if (vehicle.id.text == name) return &vehicle;
  return nullptr;
}

}  // namespace

std::optional<PlanePoint> sign_place(const File& file, const SignReference& sign) {
  if (sign.kind == SignReference::Kind::point) return PlanePoint{sign.point.x, sign.point.y};
  for (const Light& light : file.lights)
    if (light.id.text == sign.name.text) return PlanePoint{light.coords.x, light.coords.y};
  for (const Tree& tree : file.trees)
    if (tree.id.text == sign.name.text) return PlanePoint{tree.coords.x, tree.coords.y};
  return std::nullopt;
}

std::optional<Direction> way_in_heading(const File& file, const SceneLayout& layout,
                                        const Vehicle& vehicle) {
  if (vehicle.init_direction) {
    const Direction heading = vehicle.init_direction->value;
    if (layout.approach(heading)) return heading;
    return std::nullopt;
  }
  if (vehicle.start_sign)
    if (auto place = sign_place(file, *vehicle.start_sign)) return heading_towards(layout, *place);
  return std::nullopt;
}

std::optional<int> fixed_start_lane(const File& file, const Vehicle& vehicle, int lanes) {
  if (lanes == 1) return 0;
  if (auto lane = lane_for_chain(vehicle, lanes)) return lane;
  for (const Collision& collision : file.collisions) {
    const bool actor = collision.actor.id.text == vehicle.id.text;
    if (!actor && collision.victim.id.text != vehicle.id.text) continue;
    const Vehicle* other =
        vehicle_named(file, actor ? collision.victim.id.text : collision.actor.id.text);
    if (!other || !other->init_direction || !vehicle.init_direction ||
        other->init_direction->value != vehicle.init_direction->value)
      continue;
    if (auto lane = lane_changed_to(*other, lanes)) return lane;
  }
  return std::nullopt;
}

}  // namespace scenfuzz::accident
