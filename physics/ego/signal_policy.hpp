// How a law-abiding driver uses its vehicle's signals: the lights the weather and the time of
// day ask for, the indicators before a manoeuvre, brake lights, the high beam dipped for others,
// hazard lights after an emergency stop or a collision, and a short horn in an emergency. Plain
// data in, VehicleSignals out; the figures are documented in docs/simulation.md ("Vehicle
// signals"). The reference driver's signals come from here (ego_signals.hpp), the NPCs' lights
// and brake lights too.
#pragma once

#include <span>

#include "physics/actors/kinematics.hpp"
#include "physics/actors/vehicle_signals.hpp"
#include "physics/ego/perception.hpp"
#include "physics/ego/route_indications.hpp"

namespace scenfuzz {

struct SignalSettings {
  IndicationNotice notice;
  double low_beam_darkness = 0;     // low beams on above this darkness: from dusk to dawn
  double high_beam_darkness = 0.5;  // night (19:00-06:00): the high beam may be on
  double poor_visibility = 100;     // m: below it, low beams and fog lights
  double oncoming_dip = 150;        // m: an oncoming vehicle nearer dips the high beam
  double ahead_dip = 100;           // m: so does one ahead going the same way
  double braking = 0.5;             // m/s^2: decelerating harder lights the brake lights
  double standing = 0.1;            // m/s: slower is standing (held on the brake)
  double hazard_release = 2.0;      // m/s: hazard lights go off once it drives on this fast
  double horn_time = 1.0;           // s the horn sounds at the start of an emergency brake
  double horn_speed = 1.0;          // m/s: slower, braking alone suffices: no horn
};

// What the weather and the light are for a whole run.
struct SignalWeather {
  double darkness = 0;         // perception.hpp's Conditions::darkness
  double visibility = 1e9;     // m: how far a vehicle can be seen in this weather by day
  bool precipitation = false;  // rain or snow
};

// The run's weather as SignalWeather: the visibility is perception's vehicle range in this
// weather by day (`clear` degraded by fog, rain and snow, not darkness).
SignalWeather signal_weather(const Conditions& conditions, const PerceptionSettings& clear);

// Low beams (dusk to dawn, or poor visibility), fog lights (poor visibility) and wipers (rain
// or snow): what the weather asks of every vehicle, the whole run long.
VehicleSignals weather_signals(const SignalWeather& weather, const SignalSettings& settings = {});

// Brake lights: decelerating harder than settings.braking, or standing held on the brake.
VehicleSignals brake_lights(double acceleration, double speed, bool held_when_standing,
                            const SignalSettings& settings = {});

// Whether the high beam may be on: night, no poor visibility, and no perceived vehicle coming
// towards the ego within oncoming_dip nor one ahead going its way within ahead_dip.
bool high_beam_allowed(const KinematicState& ego, std::span<const WorldObject> objects,
                       const SignalWeather& weather, const SignalSettings& settings = {});

// What the ego's driver does this step, for the signals that depend on it.
struct EgoSignalInput {
  double time = 0;
  KinematicState ego;
  double acceleration = 0;               // m/s^2 it asks for this step
  VehicleSignals indicator = 0;          // from its route and overtaking (ego_signals.hpp)
  std::span<const WorldObject> objects;  // what it perceives
  bool emergency = false;                // it brakes fully for an object in its path
  bool collided = false;                 // it has collided (this step or before)
  VehicleSignals weather_lights = 0;     // weather_signals(the run's weather), worked out once
};

// What the ego remembers between steps: hazard lights on until it drives on, when its current
// emergency brake began.
struct SignalMemory {
  bool hazard = false;
  double emergency_since = -1;  // s; -1 while not braking for an emergency
};

// The ego's signals this step: input.weather_lights, and as follows. Hazard lights: once it stands
// after an emergency brake, or after a collision, until it drives on faster than hazard_release
// (the hazard replaces the indicator). Horn: the first horn_time seconds of an emergency brake
// while faster than horn_speed (an object about to be in its path when braking alone may not
// suffice).
VehicleSignals ego_signals(const EgoSignalInput& input, const SignalWeather& weather,
                           SignalMemory& memory, const SignalSettings& settings = {});

}  // namespace scenfuzz
