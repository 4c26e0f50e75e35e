// The observation a failing plugin was last handed, as the JSON a finding carries.
#include "physics/ego/observation_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace scenfuzz {
namespace {

using nlohmann::json;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

scenfuzz_observation two_objects_and_three_route_points() {
  scenfuzz_observation observation{};
  observation.ego = {1.5, 10, -2, 0.25, 7.5, -1, 0.01, 0.02};
  observation.object_count = 2;
  observation.objects[0] = {4, SCENFUZZ_OBJECT_VEHICLE, 30, -2, 0, 6, 4.7, 1.85};
  observation.objects[1] = {9, SCENFUZZ_OBJECT_PEDESTRIAN, 20, 3, 1.57, 1.2, 0.5, 0.5};
  observation.objects[2] = {99, SCENFUZZ_OBJECT_OBSTACLE, 1, 1, 1, 1, 1, 1};  // beyond the count
  observation.route_point_count = 3;
  for (uint32_t i = 0; i < 3; ++i) observation.route[i] = {10.0 + 2 * i, -2, 0, 13.9};
  observation.distance_to_target = kInfinity;
  observation.light = SCENFUZZ_LIGHT_RED;
  observation.light_distance = 42;
  observation.stop_sign_distance = kInfinity;
  return observation;
}

TEST(ObservationJson, WritesEveryFieldTheObservationHolds) {
  const json document = json::parse(observation_json(two_objects_and_three_route_points()));
  EXPECT_EQ(document["ego"]["time"], 1.5);
  EXPECT_EQ(document["ego"]["x"], 10.0);
  EXPECT_EQ(document["ego"]["y"], -2.0);
  EXPECT_EQ(document["ego"]["heading"], 0.25);
  EXPECT_EQ(document["ego"]["speed"], 7.5);
  EXPECT_EQ(document["ego"]["acceleration"], -1.0);
  EXPECT_EQ(document["ego"]["yaw_rate"], 0.01);
  EXPECT_EQ(document["ego"]["steering_angle"], 0.02);
  ASSERT_EQ(document["objects"].size(), 2u) << "only object_count objects";
  EXPECT_EQ(document["objects"][0]["id"], 4);
  EXPECT_EQ(document["objects"][0]["kind"], "vehicle");
  EXPECT_EQ(document["objects"][0]["x"], 30.0);
  EXPECT_EQ(document["objects"][0]["length"], 4.7);
  EXPECT_EQ(document["objects"][1]["kind"], "pedestrian");
  EXPECT_EQ(document["objects"][1]["heading"], 1.57);
  ASSERT_EQ(document["route"].size(), 3u) << "only route_point_count points";
  EXPECT_EQ(document["route"][2]["x"], 14.0);
  EXPECT_EQ(document["route"][2]["speed_limit"], 13.9);
  EXPECT_EQ(document["light"], "red");
  EXPECT_EQ(document["light_distance"], 42.0);
}

TEST(ObservationJson, NoTargetNoSignAndNoLightAreNullAndNone) {
  scenfuzz_observation observation = two_objects_and_three_route_points();
  observation.light = SCENFUZZ_LIGHT_NONE;
  observation.light_distance = kInfinity;
  const std::string text = observation_json(observation);
  const json document = json::parse(text);  // JSON has no Infinity: it must still parse
  EXPECT_TRUE(document["distance_to_target"].is_null());
  EXPECT_TRUE(document["stop_sign_distance"].is_null());
  EXPECT_TRUE(document["light_distance"].is_null());
  EXPECT_EQ(document["light"], "none");
}

TEST(ObservationJson, IsOneCompactLine) {
  const std::string text = observation_json(two_objects_and_three_route_points());
  EXPECT_EQ(text.find('\n'), std::string::npos);
  EXPECT_EQ(text.find(": "), std::string::npos);
  EXPECT_EQ(text.front(), '{');
}

TEST(ObservationJson, CountsBeyondTheArraysAreCappedAndUnknownKindsStayNumbers) {
  scenfuzz_observation observation{};
  observation.object_count = SCENFUZZ_MAX_OBJECTS + 5;
  observation.route_point_count = SCENFUZZ_ROUTE_POINTS + 5;
  observation.objects[0].kind = 17;
  observation.light = 9;
  const json document = json::parse(observation_json(observation));
  EXPECT_EQ(document["objects"].size(), std::size_t{SCENFUZZ_MAX_OBJECTS});
  EXPECT_EQ(document["route"].size(), std::size_t{SCENFUZZ_ROUTE_POINTS});
  EXPECT_EQ(document["objects"][0]["kind"], 17);
  EXPECT_EQ(document["light"], 9);
}

}  // namespace
}  // namespace scenfuzz
