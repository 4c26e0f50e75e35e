// The actor class table: one row per category, sizes from corpora/README.md, turning radii, and
// the model names scenario files use.
#include "physics/actors/actor_class.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace scenfuzz {
namespace {

TEST(ActorClassTable, HasOneRowPerCategoryInEnumOrder) {
  const auto classes = actor_classes();
  ASSERT_EQ(classes.size(), 8u);
  for (std::size_t i = 0; i < classes.size(); ++i) {
    const auto category = static_cast<ActorCategory>(i);
    EXPECT_EQ(classes[i].category, category);
    EXPECT_EQ(&actor_class(category), &classes[i]);
    EXPECT_EQ(category_for_model(classes[i].name), category) << classes[i].name;
  }
}

TEST(ActorClassTable, LimitsArePositiveAndConsistent) {
  for (const ActorClass& actor : actor_classes()) {
    SCOPED_TRACE(std::string(actor.name));
    EXPECT_GT(actor.length, 0);
    EXPECT_GT(actor.width, 0);
    EXPECT_GT(actor.height, 0);
    EXPECT_GT(actor.max_speed, 0);
    EXPECT_GT(actor.max_acceleration, 0);
    EXPECT_GT(actor.max_deceleration, actor.comfortable_deceleration);
    EXPECT_GT(actor.comfortable_deceleration, 0);
    if (actor.category == ActorCategory::pedestrian) {
      EXPECT_EQ(actor.wheelbase, 0);
      EXPECT_EQ(actor.min_turning_radius(), 0);
    } else {
      EXPECT_GT(actor.wheelbase, 0);
      EXPECT_LT(actor.wheelbase, actor.length);
      EXPECT_GT(actor.max_steering_angle, 0);
      EXPECT_LT(actor.max_steering_angle, std::numbers::pi / 3);
      EXPECT_GT(actor.max_steering_rate, 0);
      EXPECT_GT(actor.min_turning_radius(), actor.wheelbase / 2);
    }
  }
}

TEST(ActorClassTable, SizesMatchTheCorpusConventions) {
  const ActorClass& van = actor_class(ActorCategory::van);
  EXPECT_DOUBLE_EQ(van.length, 5.5);
  EXPECT_DOUBLE_EQ(van.width, 2.0);
  EXPECT_DOUBLE_EQ(van.height, 2.4);
  const ActorClass& truck = actor_class(ActorCategory::truck);
  EXPECT_DOUBLE_EQ(truck.length, 8.5);
  EXPECT_DOUBLE_EQ(truck.width, 2.5);
  const ActorClass& bus = actor_class(ActorCategory::bus);
  EXPECT_DOUBLE_EQ(bus.length, 12.0);
  EXPECT_DOUBLE_EQ(bus.width, 2.55);
  const ActorClass& bicycle = actor_class(ActorCategory::bicycle);
  EXPECT_DOUBLE_EQ(bicycle.length, 1.8);
  EXPECT_DOUBLE_EQ(bicycle.width, 0.6);
  const ActorClass& car = actor_class(ActorCategory::car);
  EXPECT_NEAR(car.length, 4.7, 0.2);
  EXPECT_NEAR(car.width, 1.85, 0.1);
  EXPECT_DOUBLE_EQ(car.wheelbase, 2.8);
  EXPECT_NEAR(actor_class(ActorCategory::pedestrian).max_speed, 3.0, 1e-12);
}

TEST(ActorClassTable, CarTurningRadiusFollowsTheCentreReferenceFormula) {
  const ActorClass& car = actor_class(ActorCategory::car);
  // Rear axle 1.4 m behind the centre, 35 degrees of lock: the rear axle turns on a circle of
  // radius L / tan(delta) = 3.999 m, the centre on the hypotenuse with l_r.
  const double rear_axle_radius = car.wheelbase / std::tan(car.max_steering_angle);
  EXPECT_NEAR(car.min_turning_radius(), std::hypot(rear_axle_radius, car.wheelbase / 2), 1e-9);
  EXPECT_NEAR(car.min_turning_radius(), 4.236, 0.01);
}

TEST(ActorClassModels, GeneralKindsAreCaseInsensitive) {
  EXPECT_EQ(category_for_model("car"), ActorCategory::car);
  EXPECT_EQ(category_for_model("CAR"), ActorCategory::car);
  EXPECT_EQ(category_for_model("Van"), ActorCategory::van);
  EXPECT_EQ(category_for_model("Truck"), ActorCategory::truck);
  EXPECT_EQ(category_for_model("Bus"), ActorCategory::bus);
  EXPECT_EQ(category_for_model("Bicycle"), ActorCategory::bicycle);
  EXPECT_EQ(category_for_model("motorcycle"), ActorCategory::motorbicycle);
  EXPECT_EQ(category_for_model("Motorbike"), ActorCategory::motorbicycle);
  EXPECT_EQ(category_for_model("motorbicycle"), ActorCategory::motorbicycle);
  EXPECT_EQ(category_for_model("tricycle"), ActorCategory::tricycle);
  EXPECT_EQ(category_for_model("Pedestrian"), ActorCategory::pedestrian);
}

TEST(ActorClassModels, LgsvlModelsAsScenarioFilesWriteThem) {
  EXPECT_EQ(category_for_model("Sedan"), ActorCategory::car);
  EXPECT_EQ(category_for_model("SUV"), ActorCategory::car);
  EXPECT_EQ(category_for_model("Jeep"), ActorCategory::car);
  EXPECT_EQ(category_for_model("Hatchback"), ActorCategory::car);
  EXPECT_EQ(category_for_model("BoxTruck"), ActorCategory::truck);
  EXPECT_EQ(category_for_model("DeliveryTruck"), ActorCategory::truck);
  EXPECT_EQ(category_for_model("SchoolBus"), ActorCategory::bus);
  EXPECT_EQ(category_for_model("Bicyclist"), ActorCategory::bicycle);
  EXPECT_EQ(category_for_model("Lincoln2017MKZ"), ActorCategory::car);
  EXPECT_EQ(category_for_model("Lincoln2017MKZ_LGSVL"), ActorCategory::car);
  EXPECT_EQ(category_for_model("Lincoln2017MKZ (Apollo 5.0)"), ActorCategory::car);
  EXPECT_EQ(category_for_model("Lincoln MKZ 2017"), ActorCategory::car);
  EXPECT_EQ(category_for_model("gt_sensors"), ActorCategory::car);
  EXPECT_EQ(category_for_model("Bob"), ActorCategory::pedestrian);
}

TEST(ActorClassModels, CarlaBlueprints) {
  EXPECT_EQ(category_for_model("vehicle.tesla.model3"), ActorCategory::car);
  EXPECT_EQ(category_for_model("vehicle.lincoln.mkz_2020"), ActorCategory::car);
  EXPECT_EQ(category_for_model("vehicle.carlamotors.carlacola"), ActorCategory::truck);
  EXPECT_EQ(category_for_model("vehicle.mitsubishi.fusorosa"), ActorCategory::bus);
  EXPECT_EQ(category_for_model("vehicle.mercedes.sprinter"), ActorCategory::van);
  EXPECT_EQ(category_for_model("vehicle.diamondback.century"), ActorCategory::bicycle);
  EXPECT_EQ(category_for_model("vehicle.harley-davidson.low_rider"), ActorCategory::motorbicycle);
  EXPECT_EQ(category_for_model("walker.pedestrian.0001"), ActorCategory::pedestrian);
  EXPECT_EQ(category_for_model("vehicle.unknown.spaceship"), std::nullopt);
}

// Every model the seeds in corpora/avunit and the examples in shared/examples write.
TEST(ActorClassModels, EveryModelTheCorporaUseMaps) {
  for (const char* model : {"Lincoln2017MKZ", "Sedan", "SUV", "Van", "Truck", "Bus", "Bicycle",
                            "gt_sensors", "Lincoln MKZ 2017"}) {
    EXPECT_TRUE(category_for_model(model).has_value()) << model;
  }
}

TEST(ActorClassModels, UnknownNamesAreNullopt) {
  EXPECT_EQ(category_for_model(""), std::nullopt);
  EXPECT_EQ(category_for_model("   "), std::nullopt);
  EXPECT_EQ(category_for_model("Spaceship"), std::nullopt);
  EXPECT_EQ(category_for_model("ca"), std::nullopt);
  // A short name is not a prefix rule: "cart" is not a car.
  EXPECT_EQ(category_for_model("cart"), std::nullopt);
}

}  // namespace
}  // namespace scenfuzz
