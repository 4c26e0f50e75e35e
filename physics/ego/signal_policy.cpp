// The law-abiding driver's use of its vehicle's signals (signal_policy.hpp).
#include "physics/ego/signal_policy.hpp"

#include <cmath>

namespace scenfuzz {

SignalWeather signal_weather(const Conditions& conditions, const PerceptionSettings& clear) {
  Conditions by_day = conditions;
  by_day.darkness = 0;
  return {conditions.darkness, degraded(clear, by_day).vehicle_range,
          conditions.rain > 0 || conditions.snow > 0};
}

VehicleSignals weather_signals(const SignalWeather& weather, const SignalSettings& settings) {
  VehicleSignals signals = 0;
  const bool poor_visibility = weather.visibility < settings.poor_visibility;
  if (weather.darkness > settings.low_beam_darkness || poor_visibility)
    signals |= vehicle_signal::low_beam;
  if (poor_visibility) signals |= vehicle_signal::fog_lights;
  if (weather.precipitation) signals |= vehicle_signal::wipers;
  return signals;
}

VehicleSignals brake_lights(double acceleration, double speed, bool held_when_standing,
                            const SignalSettings& settings) {
  const bool braking = acceleration < -settings.braking;
  const bool held = held_when_standing && std::abs(speed) < settings.standing;
  return braking || held ? vehicle_signal::brake_lights : VehicleSignals{0};
}

bool high_beam_allowed(const KinematicState& ego, std::span<const WorldObject> objects,
                       const SignalWeather& weather, const SignalSettings& settings) {
  if (weather.darkness < settings.high_beam_darkness) return false;
  if (weather.visibility < settings.poor_visibility) return false;
  const double c = std::cos(ego.heading), s = std::sin(ego.heading);
  for (const WorldObject& object : objects) {
    if (object.kind != TraceActorKind::vehicle) continue;
    const double dx = object.x - ego.x, dy = object.y - ego.y;
    const double along = dx * c + dy * s;
    if (along <= 0) continue;  // beside or behind: the beam does not reach its driver
    const double facing = std::cos(object.heading - ego.heading);
    const double distance = std::hypot(dx, dy);
    // Coming towards the ego (headings more than 90 degrees apart) or going its way.
    if (facing < 0 ? distance < settings.oncoming_dip : distance < settings.ahead_dip) return false;
  }
  return true;
}

VehicleSignals ego_signals(const EgoSignalInput& input, const SignalWeather& weather,
                           SignalMemory& memory, const SignalSettings& settings) {
  const double speed = input.ego.speed;
  VehicleSignals signals = input.weather_lights;
  if (weather.darkness >= settings.high_beam_darkness &&
      high_beam_allowed(input.ego, input.objects, weather, settings))
    signals |= vehicle_signal::high_beam;
  signals |= brake_lights(input.acceleration, speed, true, settings);

  // An emergency brake lasts from the first emergency step until the ego stands or stops
  // braking: the time-to-collision test that starts it may lapse as the ego slows.
  if (input.emergency && memory.emergency_since < 0) memory.emergency_since = input.time;
  const bool standing = speed < settings.standing;
  if (standing && (memory.emergency_since >= 0 || input.collided)) memory.hazard = true;
  if (speed > settings.hazard_release) memory.hazard = false;
  if (input.emergency && speed > settings.horn_speed &&
      input.time - memory.emergency_since < settings.horn_time)
    signals |= vehicle_signal::horn;
  if (!input.emergency && (standing || input.acceleration >= 0)) memory.emergency_since = -1;

  signals |= memory.hazard ? vehicle_signal::hazard_lights : input.indicator;
  return signals;
}

}  // namespace scenfuzz
