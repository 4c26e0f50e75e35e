// The actor class table and the mapping from scenario model names onto it. Figures are typical
// EU/US vehicles of each kind, matched to the sizes corpora/README.md gives for the seeds'
// vehicle types (docs/simulation.md lists them with their sources).
#include "physics/actors/actor_class.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "lang/demand.hpp"

namespace scenfuzz {
namespace {

constexpr double degrees(double value) { return value * std::numbers::pi / 180.0; }

// In enum order: actor_class() indexes the table by the category.
constexpr std::array<ActorClass, 8> kActorClasses{{
    // A mid-size sedan (the seeds' "Sedan"; the ego's Lincoln MKZ is 4.93 x 1.86 x 1.48).
    {.category = ActorCategory::car,
     .name = "car",
     .length = 4.7,
     .width = 1.85,
     .height = 1.45,
     .wheelbase = 2.8,
     .max_speed = 50.0,
     .max_acceleration = 3.5,
     .max_deceleration = 8.0,
     .comfortable_deceleration = 3.0,
     .comfortable_lateral_acceleration = 3.0,
     .max_jerk = 10.0,
     .max_steering_angle = degrees(35),
     .max_steering_rate = 0.7},
    // A large panel van (Mercedes Sprinter, Ford Transit class).
    {.category = ActorCategory::van,
     .name = "van",
     .length = 5.5,
     .width = 2.0,
     .height = 2.4,
     .wheelbase = 3.4,
     .max_speed = 40.0,
     .max_acceleration = 2.5,
     .max_deceleration = 7.5,
     .comfortable_deceleration = 2.5,
     .comfortable_lateral_acceleration = 2.5,
     .max_jerk = 8.0,
     .max_steering_angle = degrees(35),
     .max_steering_rate = 0.6},
    // A 12 m city bus (Mercedes Citaro class); slow acceleration and braking for standing
    // passengers, a large steering lock to reach the EU's 12.5 m turning circle.
    {.category = ActorCategory::bus,
     .name = "bus",
     .length = 12.0,
     .width = 2.55,
     .height = 3.2,
     .wheelbase = 6.0,
     .max_speed = 25.0,
     .max_acceleration = 1.5,
     .max_deceleration = 6.0,
     .comfortable_deceleration = 1.5,
     .comfortable_lateral_acceleration = 1.5,
     .max_jerk = 5.0,
     .max_steering_angle = degrees(45),
     .max_steering_rate = 0.5},
    // A two-axle rigid delivery truck (box truck); EU trucks are limited to 90 km/h.
    {.category = ActorCategory::truck,
     .name = "truck",
     .length = 8.5,
     .width = 2.5,
     .height = 3.2,
     .wheelbase = 5.0,
     .max_speed = 25.0,
     .max_acceleration = 1.5,
     .max_deceleration = 6.5,
     .comfortable_deceleration = 2.0,
     .comfortable_lateral_acceleration = 2.0,
     .max_jerk = 6.0,
     .max_steering_angle = degrees(40),
     .max_steering_rate = 0.5},
    // A bicycle with its rider.
    {.category = ActorCategory::bicycle,
     .name = "bicycle",
     .length = 1.8,
     .width = 0.6,
     .height = 1.7,
     .wheelbase = 1.05,
     .max_speed = 12.0,
     .max_acceleration = 1.5,
     .max_deceleration = 4.0,
     .comfortable_deceleration = 2.0,
     .comfortable_lateral_acceleration = 2.5,
     .max_jerk = 5.0,
     .max_steering_angle = degrees(40),
     .max_steering_rate = 1.5},
    // A mid-size motorcycle with its rider.
    {.category = ActorCategory::motorbicycle,
     .name = "motorbicycle",
     .length = 2.2,
     .width = 0.8,
     .height = 1.5,
     .wheelbase = 1.45,
     .max_speed = 50.0,
     .max_acceleration = 5.0,
     .max_deceleration = 7.0,
     .comfortable_deceleration = 3.0,
     .comfortable_lateral_acceleration = 4.0,
     .max_jerk = 10.0,
     .max_steering_angle = degrees(35),
     .max_steering_rate = 1.0},
    // A motorised three-wheeler (auto rickshaw, cargo tricycle), what Apollo calls a tricycle.
    {.category = ActorCategory::tricycle,
     .name = "tricycle",
     .length = 2.8,
     .width = 1.3,
     .height = 1.8,
     .wheelbase = 1.9,
     .max_speed = 14.0,
     .max_acceleration = 2.0,
     .max_deceleration = 5.0,
     .comfortable_deceleration = 2.0,
     .comfortable_lateral_acceleration = 2.0,
     .max_jerk = 6.0,
     .max_steering_angle = degrees(40),
     .max_steering_rate = 0.8},
    // An adult; length and width are the body cylinder's diameter. 3 m/s is a run.
    {.category = ActorCategory::pedestrian,
     .name = "pedestrian",
     .length = 0.6,
     .width = 0.6,
     .height = 1.75,
     .wheelbase = 0,
     .max_speed = 3.0,
     .max_acceleration = 1.5,
     .max_deceleration = 2.5,
     .comfortable_deceleration = 1.0,
     .comfortable_lateral_acceleration = 0.0,
     .max_jerk = 10.0,
     .max_steering_angle = 0,
     .max_steering_rate = 0},
}};

struct ModelName {
  std::string_view name;  // already normalized: lower case, letters and digits only
  ActorCategory category;
};

// General kinds, LGSVL/SVL model names, Apollo obstacle types and the model part of CARLA
// blueprint ids ("vehicle.tesla.model3" -> "model3"), compared after normalized_name.
constexpr std::array kModelNames{
    // General kinds and their usual synonyms.
    ModelName{"car", ActorCategory::car},
    ModelName{"vehicle", ActorCategory::car},
    ModelName{"van", ActorCategory::van},
    ModelName{"bus", ActorCategory::bus},
    ModelName{"truck", ActorCategory::truck},
    ModelName{"bicycle", ActorCategory::bicycle},
    ModelName{"bike", ActorCategory::bicycle},
    ModelName{"cyclist", ActorCategory::bicycle},
    ModelName{"bicyclist", ActorCategory::bicycle},
    ModelName{"motorbicycle", ActorCategory::motorbicycle},
    ModelName{"motorcycle", ActorCategory::motorbicycle},
    ModelName{"motorbike", ActorCategory::motorbicycle},
    ModelName{"motorcyclist", ActorCategory::motorbicycle},
    ModelName{"scooter", ActorCategory::motorbicycle},
    ModelName{"tricycle", ActorCategory::tricycle},
    ModelName{"tricyclist", ActorCategory::tricycle},
    ModelName{"pedestrian", ActorCategory::pedestrian},
    ModelName{"walker", ActorCategory::pedestrian},
    ModelName{"person", ActorCategory::pedestrian},
    // LGSVL/SVL NPC vehicles.
    ModelName{"sedan", ActorCategory::car},
    ModelName{"suv", ActorCategory::car},
    ModelName{"jeep", ActorCategory::car},
    ModelName{"hatchback", ActorCategory::car},
    ModelName{"boxtruck", ActorCategory::truck},
    ModelName{"deliverytruck", ActorCategory::truck},
    ModelName{"schoolbus", ActorCategory::bus},
    // LGSVL/SVL ego vehicles ("Lincoln2017MKZ_LGSVL", "Lincoln MKZ 2017" via the prefix rule),
    // and the sensor configuration LawBreaker's scenarios write as the ego's model.
    ModelName{"lincoln2017mkz", ActorCategory::car},
    ModelName{"lincolnmkz2017", ActorCategory::car},
    ModelName{"jaguar2015xe", ActorCategory::car},
    ModelName{"lexus2016rxhybrid", ActorCategory::car},
    ModelName{"gtsensors", ActorCategory::car},
    // CARLA blueprints (model part).
    ModelName{"a2", ActorCategory::car},
    ModelName{"etron", ActorCategory::car},
    ModelName{"tt", ActorCategory::car},
    ModelName{"grandtourer", ActorCategory::car},
    ModelName{"impala", ActorCategory::car},
    ModelName{"c3", ActorCategory::car},
    ModelName{"charger2020", ActorCategory::car},
    ModelName{"chargerpolice", ActorCategory::car},
    ModelName{"chargerpolice2020", ActorCategory::car},
    ModelName{"mustang", ActorCategory::car},
    ModelName{"crown", ActorCategory::car},
    ModelName{"wranglerrubicon", ActorCategory::car},
    ModelName{"mkz2017", ActorCategory::car},
    ModelName{"mkz2020", ActorCategory::car},
    ModelName{"coupe", ActorCategory::car},
    ModelName{"coupe2020", ActorCategory::car},
    ModelName{"microlino", ActorCategory::car},
    ModelName{"coopers", ActorCategory::car},
    ModelName{"cooper2021", ActorCategory::car},
    ModelName{"micra", ActorCategory::car},
    ModelName{"patrol", ActorCategory::car},
    ModelName{"patrol2021", ActorCategory::car},
    ModelName{"leon", ActorCategory::car},
    ModelName{"model3", ActorCategory::car},
    ModelName{"prius", ActorCategory::car},
    ModelName{"cybertruck", ActorCategory::car},
    ModelName{"sprinter", ActorCategory::van},
    ModelName{"t2", ActorCategory::van},
    ModelName{"t22021", ActorCategory::van},
    ModelName{"ambulance", ActorCategory::van},
    ModelName{"carlacola", ActorCategory::truck},
    ModelName{"firetruck", ActorCategory::truck},
    ModelName{"europeanhgv", ActorCategory::truck},
    ModelName{"fusorosa", ActorCategory::bus},
    ModelName{"lowrider", ActorCategory::motorbicycle},
    ModelName{"ninja", ActorCategory::motorbicycle},
    ModelName{"zx125", ActorCategory::motorbicycle},
    ModelName{"yzf", ActorCategory::motorbicycle},
    ModelName{"crossbike", ActorCategory::bicycle},
    ModelName{"century", ActorCategory::bicycle},
    ModelName{"omafiets", ActorCategory::bicycle},
    // LGSVL/SVL pedestrians.
    ModelName{"bob", ActorCategory::pedestrian},
    ModelName{"entrepreneurfemale", ActorCategory::pedestrian},
    ModelName{"howard", ActorCategory::pedestrian},
    ModelName{"johny", ActorCategory::pedestrian},
    ModelName{"pamela", ActorCategory::pedestrian},
    ModelName{"presley", ActorCategory::pedestrian},
    ModelName{"robin", ActorCategory::pedestrian},
    ModelName{"stephen", ActorCategory::pedestrian},
    ModelName{"zoe", ActorCategory::pedestrian},
};

// Lower case with everything but letters and digits dropped, so "Lincoln2017MKZ_LGSVL",
// "Lincoln MKZ 2017" and "School-Bus" compare by their letters alone.
std::string normalized_name(std::string_view name) {
  std::string result;
  for (char c : name) {
    if (c >= 'A' && c <= 'Z') {
      result += static_cast<char>(c - 'A' + 'a');
    } else if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) {
      result += c;
    }
  }
  return result;
}

std::optional<ActorCategory> exact_match(std::string_view normalized) {
  for (const ModelName& model : kModelNames) {
    if (normalized == model.name) return model.category;
  }
  return std::nullopt;
}

}  // namespace

double ActorClass::min_turning_radius() const {
  if (wheelbase <= 0 || max_steering_angle <= 0) return 0;
  const double rear_to_centre = wheelbase / 2;
  const double slip = std::atan(rear_to_centre / wheelbase * std::tan(max_steering_angle));
  return rear_to_centre / std::sin(slip);
}

std::span<const ActorClass> actor_classes() { return kActorClasses; }

const ActorClass& actor_class(ActorCategory category) {
  const auto index = static_cast<std::size_t>(category);
  SCENFUZZ_DEMAND(index < kActorClasses.size());
  return kActorClasses[index];
}

std::optional<ActorCategory> category_for_model(std::string_view model) {
  // CARLA blueprint ids: "walker.pedestrian.0001" is a pedestrian, "vehicle.<make>.<model>"
  // is looked up by its model part.
  if (const std::size_t dot = model.find('.'); dot != std::string_view::npos) {
    const std::string kind = normalized_name(model.substr(0, dot));
    const std::string_view rest = model.substr(dot + 1);
    if (kind == "walker") return ActorCategory::pedestrian;
    if (kind == "vehicle") {
      const std::size_t model_dot = rest.rfind('.');
      return exact_match(
          normalized_name(model_dot == std::string_view::npos ? rest : rest.substr(model_dot + 1)));
    }
  }
  const std::string normalized = normalized_name(model);
  if (normalized.empty()) return std::nullopt;
  if (auto category = exact_match(normalized)) return category;
  // Variants of a known model: "Lincoln2017MKZ_LGSVL", "Lincoln2017MKZ (Apollo 5.0)".
  for (const ModelName& known : kModelNames) {
    // Short names ("car", "suv", "tt") would claim unrelated words as prefixes.
    if (known.name.size() >= 5 && normalized.starts_with(known.name)) return known.category;
  }
  return std::nullopt;
}

}  // namespace scenfuzz
