// What kind of road user an actor is, and the dimensions and limits that come with it: one row
// per category (docs/simulation.md has the table and its sources). Specific model names that
// scenario files use ("Sedan", "SUV", "Lincoln2017MKZ", "SchoolBus") map onto a category.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace scenfuzz {

enum class ActorCategory { car, van, bus, truck, bicycle, motorbicycle, tricycle, pedestrian };

struct ActorClass {
  ActorCategory category = ActorCategory::car;
  std::string_view name;        // "car", "van", ... as scenario files write the general kinds
  double length = 0;            // m; a pedestrian's body diameter
  double width = 0;             // m; a pedestrian's body diameter
  double height = 0;            // m
  double wheelbase = 0;         // m; 0 for pedestrians
  double max_speed = 0;         // m/s
  double max_acceleration = 0;  // m/s^2
  double max_deceleration = 0;  // m/s^2, positive: full braking
  double comfortable_deceleration = 0;  // m/s^2, positive: what a calm driver uses
  // m/s^2 sideways that a calm driver takes a bend with (speed^2 x curvature); 0 for pedestrians.
  double comfortable_lateral_acceleration = 0;
  double max_jerk = 0;            // m/s^3: how fast NPC motion may change its acceleration
  double max_steering_angle = 0;  // rad, front wheel; 0 for pedestrians
  double max_steering_rate = 0;   // rad/s, front wheel; 0 for pedestrians

  // Radius of the circle the body centre drives at full lock (kinematic bicycle model with the
  // reference point midway between the axles); 0 for pedestrians, who turn on the spot.
  double min_turning_radius() const;
};

std::span<const ActorClass> actor_classes();
const ActorClass& actor_class(ActorCategory category);

// The category of a model or general kind as scenario files write it, case-insensitively
// ("car", "Sedan", "SUV", "BoxTruck", "SchoolBus", "Bicyclist", "Pedestrian"); nullopt when
// the name is unknown (the caller decides whether that is a warning or an error).
std::optional<ActorCategory> category_for_model(std::string_view model);

}  // namespace scenfuzz
