// Translation from the simulation's view of the world to the plugin ABI's structs.
#include "physics/simulation/plugin_observation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scenfuzz {
namespace {

constexpr double kRoutePointSpacing = 2;  // m, as ego_plugin.h promises

std::uint32_t object_kind(TraceActorKind kind) {
  switch (kind) {
    case TraceActorKind::pedestrian: return SCENFUZZ_OBJECT_PEDESTRIAN;
    case TraceActorKind::obstacle: return SCENFUZZ_OBJECT_OBSTACLE;
    case TraceActorKind::ego:
    case TraceActorKind::vehicle: return SCENFUZZ_OBJECT_VEHICLE;
  }
  return SCENFUZZ_OBJECT_VEHICLE;
}

}  // namespace

scenfuzz_ego_config plugin_config(const SimulationSetup& setup, double dt, std::uint64_t seed) {
  scenfuzz_ego_config config{};
  config.abi_version = SCENFUZZ_EGO_ABI_VERSION;  // lowered to the plugin's (plugin_driver.cpp)
  config.dt = dt;
  config.seed = seed;
  const ActorClass& body = setup.ego_body;
  config.vehicle = {body.length,
                    body.width,
                    body.wheelbase,
                    body.max_speed,
                    body.max_acceleration,
                    body.max_deceleration,
                    body.max_steering_angle};
  config.target_x =
      setup.ego_target ? setup.ego_target->position.x : std::numeric_limits<double>::quiet_NaN();
  config.target_y =
      setup.ego_target ? setup.ego_target->position.y : std::numeric_limits<double>::quiet_NaN();
  return config;
}

void fill_observation(const RouteTracker& route, const KinematicState& ego, double t,
                      std::span<const WorldObject> perceived, std::span<const SignalColour> lights,
                      bool has_target, scenfuzz_observation& observation) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  observation.ego = {
      t, ego.x, ego.y, ego.heading, ego.speed, ego.acceleration, ego.yaw_rate, ego.steering_angle};

  std::vector<const WorldObject*> nearest;
  nearest.reserve(perceived.size());
  for (const WorldObject& object : perceived) nearest.push_back(&object);
  auto distance2 = [&](const WorldObject* o) {
    return (o->x - ego.x) * (o->x - ego.x) + (o->y - ego.y) * (o->y - ego.y);
  };
  std::stable_sort(nearest.begin(), nearest.end(), [&](const WorldObject* a, const WorldObject* b) {
    return distance2(a) < distance2(b);
  });
  std::size_t count = std::min<std::size_t>(nearest.size(), SCENFUZZ_MAX_OBJECTS);
  observation.object_count = static_cast<std::uint32_t>(count);
  for (std::size_t i = 0; i < count; ++i) {
    const WorldObject& o = *nearest[i];
    observation.objects[i] = {o.id,   object_kind(o.kind), o.x, o.y, o.heading, o.speed, o.length,
                              o.width};
  }
  // Only vehicles show signals; slots past the objects seen hold none.
  for (std::size_t i = 0; i < SCENFUZZ_MAX_OBJECTS; ++i)
    observation.object_signals[i] =
        i < count && nearest[i]->kind == TraceActorKind::vehicle ? nearest[i]->signals : 0;

  std::uint32_t points = 0;
  for (double s = route.progress();
       !route.empty() && s <= route.length() && points < SCENFUZZ_ROUTE_POINTS;
       s += kRoutePointSpacing, ++points) {
    MapPoint p = route.path().point_at(s);
    observation.route[points] = {p.x, p.y, route.path().heading_at(s), route.speed_limit_at(s)};
  }
  observation.route_point_count = points;
  observation.distance_to_target = has_target ? route.length() - route.progress() : infinity;

  observation.light = SCENFUZZ_LIGHT_NONE;
  observation.light_distance = infinity;
  observation.stop_sign_distance = infinity;
  for (const RouteFeature& feature : route.features()) {
    double ahead = feature.s - route.progress();
    if (ahead < 0) continue;
    if (feature.kind == FeatureKind::traffic_light && observation.light == SCENFUZZ_LIGHT_NONE) {
      SignalColour colour =
          feature.index < lights.size() ? lights[feature.index] : SignalColour::green;
      observation.light = colour == SignalColour::red      ? SCENFUZZ_LIGHT_RED
                          : colour == SignalColour::yellow ? SCENFUZZ_LIGHT_YELLOW
                                                           : SCENFUZZ_LIGHT_GREEN;
      observation.light_distance = ahead;
    }
    if (feature.kind == FeatureKind::stop_sign && std::isinf(observation.stop_sign_distance))
      observation.stop_sign_distance = ahead;
  }
}

}  // namespace scenfuzz
