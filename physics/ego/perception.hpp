// What the ego sees: a perception model between the true world and the driver. Objects beyond
// the detection range or outside the field of view are not seen; seen ones carry noise on
// position, heading and velocity, arrive `latency` seconds late, and are missed now and then.
// Fog, rain, snow and darkness (from the scenario's environment) shorten the range and add
// noise and misses, so that weather and time of day are real dimensions of the search. All
// randomness comes from the generator seeded at construction.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "physics/actors/kinematics.hpp"
#include "physics/ego/xoshiro256.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// Each in [0, 1]: 0 none, 1 the heaviest the model knows.
struct Conditions {
  double fog = 0;
  double rain = 0;
  double snow = 0;
  double darkness = 0;  // 0 daylight, 1 night without street light
};

// Darkness at a time of day (seconds since midnight): 0 by day, 1 by night, linear through
// dawn (05:00-07:00) and dusk (18:00-20:00).
double darkness_at(double time_of_day);

struct PerceptionSettings {
  double vehicle_range = 150;      // m, clear daylight
  double pedestrian_range = 80;    // m, clear daylight
  double field_of_view = 6.2832;   // rad, centred on the heading (2 pi: all round)
  double position_noise = 0.1;     // m, standard deviation per axis
  double heading_noise = 0.02;     // rad
  double speed_noise = 0.1;        // m/s
  double latency = 0.1;            // s between a sample and its arrival at the driver
  double miss_probability = 0.01;  // per object and step, clear conditions, close range
  double coast_time = 0.3;         // s a tracked object is kept (extrapolated) after a miss
};

// The settings worsened by the conditions (documented in docs/simulation.md).
PerceptionSettings degraded(const PerceptionSettings& clear, const Conditions& conditions);

// One object as the world knows it, or as the ego perceives it.
struct WorldObject {
  ActorId id = 0;
  TraceActorKind kind = TraceActorKind::vehicle;
  double x = 0, y = 0, heading = 0, speed = 0;
  double length = 0, width = 0;
  bool reversing = false;  // moving against its heading (KinematicState::reversing)
  // The signals it shows (a vehicle's; 0 for others): perceived with the rest of it, as late.
  VehicleSignals signals = 0;
};

class Perception {
 public:
  Perception(const PerceptionSettings& settings, std::uint64_t seed, double dt);

  // Called once per step with the true ego state and every other object. Returns the objects
  // the driver knows of now, sorted by id: detections `latency` old, and coasted tracks.
  const std::vector<WorldObject>& observe(const KinematicState& ego,
                                          std::span<const WorldObject> truth);

  const PerceptionSettings& settings() const { return settings_; }

 private:
  PerceptionSettings settings_;
  Xoshiro256 random_;
  double dt_;
  // What the sensors sampled at one step: the ego's pose then and the true objects, by id.
  struct Snapshot {
    KinematicState ego;
    std::vector<WorldObject> objects;
  };
  // The detection of an object at `last_seen` (s since the first call), extrapolated while it
  // coasts.
  struct Track {
    WorldObject object;
    double last_seen = 0;
  };
  // A ring of round(latency / dt) + 1 snapshots; history_head_ is the oldest, read this step.
  std::vector<Snapshot> history_;
  std::size_t history_head_ = 0;
  bool started_ = false;
  std::vector<Track> tracks_;  // sorted by id
  std::vector<WorldObject> output_;
  double time_ = 0;
};

}  // namespace scenfuzz
