// Malformed AVUnit: each case is a small file with one mistake. The front end must not crash, must
// fail, and must point its first error at the mistake with a message that says what it expected.
// Then error recovery (independent errors are all reported, one mistake gives one error, the error
// limit) and the formatting of a diagnostic (caret under the right character).
//
// Every parse first runs in a forked child (a death test), so a front end that crashes fails the
// one case that crashed instead of taking the whole test binary down.
//
// Cases marked `Regression:` pin front-end bugs these tests found and that were fixed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "tests/lang/malformed_harness.hpp"

namespace scenfuzz::avunit {
namespace {

// A valid scenario (lines 1-6) that the specification cases build on: they start on line 7.
const std::string kScenario =
    "ego = AV((\"lane_1\"->0), (\"lane_1\"->50));\n"
    "npc = Vehicle((\"lane_1\"->10, , 5));\n"
    "npc2 = Vehicle((\"lane_1\"->30, , 5));\n"
    "ped = Pedestrian(((1, 2), , 1));\n"
    "s = CreateScenario{load(\"m\"); ego; {npc, npc2}; {ped}; {};};\n"
    "Trace t = EXE(s);\n";

// An ego and nothing else, for the CreateScenario cases (line 1).
const std::string kEgo = "ego = AV((\"lane_1\"->0), (\"lane_1\"->50));\n";

// A scenario on line 2 whose traffic slot holds `items`, which start at column 53.
std::string with_traffic(const std::string& items) {
  return kEgo + "s = CreateScenario{load(\"m\"); ego; {}; {}; {}; {}; {" + items + "}};\n";
}

// Parses `text` in a forked child: see malformed_harness.hpp.
bool parse_survives(const std::string& text, const std::string& label) {
  return test::parse_survives({text}, label,
                              [](const std::string& t) { (void)parse(SourceFile("t.avu", t)); });
}

const Diagnostic* first_error(const Diagnostics& diagnostics) {
  for (const Diagnostic& d : diagnostics.all())
    if (d.severity == Severity::error) return &d;
  return nullptr;
}

using test::errors_of;

// ---- one mistake, one first error ----------------------------------------------------------

using test::MalformedCase;

std::vector<MalformedCase> malformed_cases() {
  const std::string& S = kScenario;
  return {
      // ---- lexer ----
      {"unterminated_string", "m = \"abc;\n", 1, 5,
       "unterminated string: expected a closing quote"},
      {"unterminated_typographic_string",
       "m = \xE2\x80\x9C"
       "abc;\n",
       1, 5, "unterminated string: expected a closing quote"},
      {"unterminated_block_comment", "x = 1;\n/* a note\nthat never ends\n", 2, 1,
       "unterminated comment: expected '*/'"},
      {"bad_character", "x = 1 @ 2;\n", 1, 7, "unexpected character '@'"},
      {"decimal_point_without_leading_digit", "x = .5;\n", 1, 5,
       "a number needs a digit before its decimal point (write 0.5)"},
      {"decimal_point_without_digits", "x = 5.;\n", 1, 5,
       "expected digits after the decimal point"},
      {"invalid_hour", "w = Environment(25:00, {});\n", 1, 17,
       "invalid time of day '25:00': expected hours 0-24 and minutes 00-59"},
      {"invalid_minute", "t = 12:60;\n", 1, 5, "invalid time of day '12:60'"},
      {"number_out_of_range", "x = 1e999;\n", 1, 5, "number '1e999' is out of range"},

      // ---- parser ----
      // A missing `;` is reported just after the token it should follow, not on the next line.
      {"missing_semicolon_after_assignment", "x = 1\ny = 2;\n", 1, 6,
       "expected ';' after the assignment, found 'y'"},
      {"missing_semicolon_after_specification", S + "t |= G(speed > 1)\n", 7, 18,
       "expected ';' after the specification, found end of file"},
      {"missing_close_paren_of_call", "a = AV((1, 2), (3, 4);\n", 1, 22,
       "expected ')' to close the argument list of 'AV', found ';'"},
      {"missing_close_paren", "x = (1 + 2;\n", 1, 11,
       "expected ')' to close the parenthesis, found ';'"},
      {"missing_close_brace_of_scenario",
       kEgo + "s = CreateScenario{load(\"m\"); ego; {}; {}; {};\n", 2, 47,
       "expected '}' to close CreateScenario{...}, found end of file"},
      {"missing_semicolon_between_scenario_slots",
       kEgo + "s = CreateScenario{load(\"m\") ego; {}; {}; {};};\n", 2, 29,
       "expected ';' after this slot of CreateScenario{...}, found 'ego'"},
      {"missing_assign", "x 1;\n", 1, 3, "expected '=' or '|=' after 'x', found number '1'"},
      {"missing_assign_after_trace_name", "Trace t EXE(s);\n", 1, 9,
       "expected '=' after the trace name, found 'EXE'"},
      {"statement_starting_with_number", "5 = x;\n", 1, 1, "expected a statement ('name = value;'"},
      {"missing_value", "x = ;\n", 1, 5, "expected a value, found ';'"},
      {"chained_comparison", "f = a < b < c;\n", 1, 11,
       "comparisons cannot be chained: write 'a < b & b < c'"},
      {"U_without_a_state", "v = Vehicle(s, U);\n", 1, 16,
       "'U' is the until operator ('a U b'); uniform motion is written 'uniform(state)' or "
       "'U(state)'"},
      {"until_without_a_left_side", S + "t |= U (speed > 1);\n", 7, 9,
       "'U(...)' with nothing before it is uniform motion and takes a state; until is written "
       "'a U b'"},
      {"frame_before_an_unfinished_lane_position", "p = IMU \"lane_1\" -> ;\n", 1, 21,
       "expected a value, found ';'"},
      {"interval_without_separator", S + "t |= G[0 5] (speed > 1);\n", 7, 10,
       "expected ':' or ',' between the bounds of the interval, found number '5'"},
      {"interval_bound_not_a_number", S + "t |= G[a:5] (speed > 1);\n", 7, 8,
       "expected a number of seconds as interval bound, found 'a'"},
      {"unclosed_interval", S + "t |= G[0, 5 (speed > 1);\n", 7, 12,
       "expected ']' to close the interval, found '('"},
      {"unknown_projection_column", S + "t |= G (t[ego].velocity > 1);\n", 7, 9,
       "a trace projection has no column 'velocity'; its columns are x, y, heading, speed"},
      {"column_of_a_number", S + "k = 3;\nt |= G (k.speed > 1);\n", 8, 9,
       "'.speed' can only follow a trace projection (trace[ego].speed)"},
      {"coordinate_range_without_y_range", "p = (1, 2) range(1, 2) & ;\n", 1, 26,
       "expected the y range '(lower, upper)' after '&', found ';'"},
      {"coordinate_range_without_ampersand", "p = (1, 2) range(1, 2);\n", 1, 23,
       "expected '&' and the y range after the x range of a coordinate, found ';'"},
      // 500 levels deep: the parser gives up at the 101st '(' (column 4 + 101).
      {"nested_too_deeply", "x = " + std::string(500, '(') + "1" + std::string(500, ')') + ";\n", 1,
       105, "expression nested too deeply"},
      {"related_without_to", "h = 90 deg related \"lane_1\"->5;\n", 1, 20,
       "expected 'to' after 'related', found string \"lane_1\""},
      {"member_without_name", "x = trafficLightAhead.;\n", 1, 23,
       "expected a name after '.', found ';'"},

      // ---- elaborator: names and values ----
      {"undefined_with_suggestion", "ego_state = 1;\nx = ego_stat + 1;\n", 2, 5,
       "'ego_stat' is not defined; did you mean 'ego_state'?"},
      {"use_before_definition", "x = y;\ny = 1;\n", 1, 5, "'y' is not defined"},
      {"inverted_range", "r = range(10, 1);\n", 1, 5,
       "inverted range: the lower bound 10 is above the upper bound 1"},
      {"empty_range", "r = range(5, 5);\n", 1, 5,
       "empty range: both bounds are 5; write the constant instead"},
      {"range_with_non_constant_bound", "a = range(1, 2);\nr = range(a, 5);\n", 2, 11,
       "a range bound must be a constant, not another range"},
      {"range_with_one_bound", "r = range(1);\n", 1, 5,
       "range(...) takes two bounds: range(lower, upper)"},
      {"negative_lane_offset", "p = \"lane_1\"->-5;\n", 1, 15,
       "an arc length along a lane cannot be negative, found -5"},
      {"heading_without_unit", "st = ((1, 2), 90, 5);\ne = AV(st, (\"lane_1\"->9));\n", 1, 15,
       "a heading needs a unit: write '90 deg' or '1.57 rad'"},
      {"division_by_zero", "x = 1/0;\n", 1, 5, "division by zero"},
      {"string_plus_number", "x = \"a\" + 1;\n", 1, 5,
       "cannot combine string \"a\" and a number with this arithmetic operator"},
      {"assign_to_temporal_operator", "G = 1;\n", 1, 1,
       "'G' is a temporal operator and cannot name a variable"},
      {"index_a_number", "x = 1;\ny = x[ego];\n", 2, 5,
       "only a trace can be indexed, not a number"},

      // ---- elaborator: environment, actors, shapes ----
      {"unknown_weather_kind", "w = Environment(12:00, {hail: 0.5});\n", 1, 25,
       "unknown weather kind 'hail': expected sunny, rain, snow, fog, wetness or cloudiness"},
      {"weather_value_out_of_range", "w = Environment(12:00, {rain: 1.5});\n", 1, 31,
       "rain must be between 0 and 1, found 1.5"},
      {"weather_kind_given_twice", "w = Environment(12:00, {rain: 0.5, rain: 0.2});\n", 1, 36,
       "'rain' is given twice"},
      {"av_with_one_argument", "e = AV((\"lane_1\"->0));\n", 1, 5,
       "AV(...) expects an initial state, a target state and an optional vehicle type: "
       "AV(init, target, type), found 1 argument"},
      {"vehicle_without_arguments", "v = Vehicle();\n", 1, 5,
       "Vehicle(...) expects Vehicle(init, motion, target, type) with the initial state first, "
       "found 0 arguments"},
      {"vehicle_with_number_as_motion", "v = Vehicle((\"lane_1\"->0), 5);\n", 1, 28,
       "expected a motion such as Waypoint(...) or uniform(...), found a number"},
      {"random_motion_on_vehicle", "v = Vehicle((\"lane_1\"->0), Random((\"lane_1\"->5)));\n", 1,
       28, "Random(...) motion is for pedestrians only"},
      {"box_with_two_dimensions", "o = Obstacle((1, 2), (box, 1, 2));\n", 1, 22,
       "a box has 3 dimensions, found 2"},
      {"box_with_negative_dimension", "o = Obstacle((1, 2), (box, 1, -2, 1));\n", 1, 31,
       "a shape's dimensions must be positive"},
      {"rgb_channel_out_of_range", "v = Vehicle((\"lane_1\"->0), , , (\"Sedan\", (300, 0, 0)));\n",
       1, 43, "an RGB colour channel is a whole number from 0 to 255"},
      {"map_name_not_a_string", "m = load(5);\n", 1, 10,
       "expected a map name in quotes, found a number"},

      // ---- elaborator: CreateScenario ----
      {"scenario_with_four_slots", kEgo + "s = CreateScenario{load(\"m\"); ego; {}; {};};\n", 2, 5,
       "CreateScenario{...} has 4 slots; expected 'load(map); ego; vehicles; pedestrians; "
       "obstacles;'"},
      {"pedestrian_in_vehicle_slot",
       kEgo + "ped = Pedestrian(((1, 2), , 1));\n" +
           "s = CreateScenario{load(\"m\"); ego; {ped}; {}; {};};\n",
       3, 37,
       "expected a Vehicle(...) in the vehicle slot of CreateScenario, found pedestrian 'ped'"},
      {"first_slot_not_load", kEgo + "s = CreateScenario{\"m\"; ego; {}; {}; {};};\n", 2, 20,
       "expected the map 'load(\"name\")' in the first slot of CreateScenario, found string "
       "\"m\""},
      {"same_npc_twice",
       kEgo + "npc = Vehicle((\"lane_1\"->10, , 5));\n" +
           "s = CreateScenario{load(\"m\"); ego; {npc, npc}; {}; {};};\n",
       3, 42, "'npc' appears twice in the scenario"},

      // ---- elaborator: scenfuzz's traffic-slot extensions (docs/avunit.md, "Extensions") ----
      {"npc_behaviour_unknown_word", with_traffic("NPCBehaviour(fast)"), 2, 66,
       "expected scripted or reactive in NPCBehaviour(...), found 'fast': write "
       "NPCBehaviour(scripted) or NPCBehaviour(reactive)"},
      {"npc_behaviour_unknown_quoted_word", with_traffic("NPCBehaviour(\"Scripted\")"), 2, 66,
       "expected scripted or reactive in NPCBehaviour(...), found string \"Scripted\""},
      {"npc_behaviour_number", with_traffic("NPCBehaviour(1)"), 2, 66,
       "expected scripted or reactive in NPCBehaviour(...), found number '1'"},
      {"npc_behaviour_without_argument", with_traffic("NPCBehaviour()"), 2, 53,
       "NPCBehaviour(...) takes one word: NPCBehaviour(scripted) or NPCBehaviour(reactive), "
       "found 0 arguments"},
      {"npc_behaviour_with_two_arguments", with_traffic("NPCBehaviour(scripted, reactive)"), 2, 53,
       "NPCBehaviour(...) takes one word: NPCBehaviour(scripted) or "
       "NPCBehaviour(reactive), found 2 arguments"},
      {"npc_behaviour_given_twice", with_traffic("NPCBehaviour(scripted), NPCBehaviour(reactive)"),
       2, 77, "NPCBehaviour(...) is given twice in the traffic slot; keep one"},
      {"npc_behaviour_in_the_vehicle_slot",
       kEgo + "b = NPCBehaviour(scripted);\n" +
           "s = CreateScenario{load(\"m\"); ego; {b}; {}; {};};\n",
       3, 37,
       "expected a Vehicle(...) in the vehicle slot of CreateScenario, found "
       "NPCBehaviour(scripted)"},
      {"number_in_the_traffic_slot", with_traffic("1"), 2, 53,
       "expected an Intersection(...), SpeedLimit(...), Flow(...), NPCBehaviour(...) or "
       "TrafficLight(...) in the traffic slot, found a number"},
      {"traffic_light_unknown_colour", with_traffic("TrafficLight(\"light_west\", blue)"), 2, 80,
       "expected red, yellow or green in TrafficLight(...), found 'blue'"},
      {"traffic_light_id_not_quoted", with_traffic("TrafficLight(light_west, red)"), 2, 66,
       "expected the map's traffic-light id in quotes in TrafficLight(...), found 'light_west'"},
      {"traffic_light_without_colour", with_traffic("TrafficLight(\"light_west\")"), 2, 53,
       "TrafficLight(...) takes a light's id and a colour: TrafficLight(\"light_id\", red), with "
       "red, yellow or green, found 1 argument"},
      {"traffic_light_given_twice",
       with_traffic("TrafficLight(\"light_west\", red), TrafficLight(\"light_west\", green)"), 2,
       86, "traffic light 'light_west' is given twice in the traffic slot; keep one"},
      {"flow_negative_rate", with_traffic("Flow(\"east_0\", -100, 10)"), 2, 68,
       "a flow's rate cannot be negative, found -100"},
      {"flow_negative_speed", with_traffic("Flow(\"east_0\", 100, -3)"), 2, 73,
       "a flow's speed cannot be negative, found -3"},
      {"flow_zero_speed", with_traffic("Flow(\"east_0\", 100, 0)"), 2, 73,
       "a flow's speed must be above 0 m/s (its vehicles must move), found 0"},
      {"flow_rate_above_a_vehicle_a_second", with_traffic("Flow(\"east_0\", 5000, 10)"), 2, 68,
       "a flow's rate cannot be above 3600 vehicles per hour (one vehicle per second per lane), "
       "found 5000"},
      {"flow_rate_range_reaching_above_a_vehicle_a_second",
       with_traffic("Flow(\"east_0\", range(1000, 4000), 10)"), 2, 68,
       "a flow's rate cannot be above 3600 vehicles per hour (one vehicle per second per lane), "
       "but it can reach 4000"},
      {"flow_speed_range_reaching_zero", with_traffic("Flow(\"east_0\", 100, range(0, 10))"), 2, 73,
       "a flow's speed must be above 0 m/s (its vehicles must move), but it can reach 0"},
      {"flow_inverted_rate_range", with_traffic("Flow(\"east_0\", range(900, 300), 10)"), 2, 68,
       "inverted range: the lower bound 900 is above the upper bound 300"},
      {"flow_inverted_speed_range", with_traffic("Flow(\"east_0\", 100, range(14, 8))"), 2, 73,
       "inverted range: the lower bound 14 is above the upper bound 8"},
      {"flow_unbounded_rate", with_traffic("Flow(\"east_0\", 100 / range(-1, 1), 10)"), 2, 68,
       "a flow's rate must be finite, but it is unbounded"},
      {"flow_with_two_arguments", with_traffic("Flow(\"east_0\", 100)"), 2, 53,
       "Flow(...) expects Flow(\"source_lane\", rate, speed) or Flow(\"source_lane\", rate, "
       "speed, \"destination_lane\"), found 2 arguments"},
      {"flow_with_five_arguments", with_traffic("Flow(\"east_0\", 100, 10, \"west_0\", 1)"), 2, 53,
       "Flow(...) expects Flow(\"source_lane\", rate, speed) or"},
      {"flow_rate_not_a_number", with_traffic("Flow(\"east_0\", \"fast\", 10)"), 2, 68,
       "expected a rate in vehicles per hour in Flow(...), found string \"fast\""},
      {"flow_speed_a_time_of_day", with_traffic("Flow(\"east_0\", 100, 12:00)"), 2, 73,
       "expected a speed in m/s in Flow(...), found a time of day"},
      {"flow_source_lane_not_a_string", with_traffic("Flow(3, 100, 10)"), 2, 58,
       "expected the source lane id in quotes in Flow(...), found a number"},
      {"flow_destination_lane_not_a_string", with_traffic("Flow(\"east_0\", 100, 10, 2)"), 2, 77,
       "expected the destination lane id in quotes in Flow(...), found a number"},
      {"flow_empty_source_lane", with_traffic("Flow(\"\", 100, 10)"), 2, 58,
       "a lane id cannot be empty"},
      {"flow_used_twice",
       kEgo + "f = Flow(\"east_0\", 100, 10);\n" +
           "s = CreateScenario{load(\"m\"); ego; {}; {}; {}; {}; {f, f}};\n",
       3, 56, "'f' appears twice in the scenario"},

      // ---- elaborator: traces and specifications ----
      {"trace_not_exe",
       kEgo + "s = CreateScenario{load(\"m\"); ego; {}; {}; {};};\nTrace t = foo(s);\n", 3, 11,
       "expected 'EXE(scenario)' after 'Trace t ='"},
      {"exe_outside_trace_declaration",
       kEgo + "s = CreateScenario{load(\"m\"); ego; {}; {}; {};};\nx = EXE(s);\n", 3, 5,
       "EXE(...) can only be used as 'Trace name = EXE(scenario);'"},
      {"satisfies_on_non_trace", "x = 1;\nx |= G(speed > 1);\n", 2, 1,
       "'x' is not a trace: declare it with 'Trace x = EXE(scenario);'"},
      {"spec_on_actor_not_in_scenario",
       S + "other = Vehicle((\"lane_1\"->70));\nt |= G(dis(t[ego], t[truth][other]) > 1);\n", 8, 20,
       "'other' is not part of the scenario that 't' executes"},
      {"projection_of_another_trace",
       S + "Trace u = EXE(s);\nt |= G(dis(u[ego], t[truth][npc]) > 1);\n", 8, 12,
       "this projection reads trace 'u', but the specification is asserted on 't'"},
      {"truth_without_agent", S + "t |= G(dis(t[ego], t[truth]) > 1);\n", 7, 20,
       "name the agent: t[truth][npc1] or t[perception][npc1]"},
      {"unknown_trace_index", S + "t |= G(dis(t[foo], t[ego]) > 1);\n", 7, 14,
       "expected ego, truth or perception inside t[...], found 'foo'"},
      {"diff_of_different_agents", S + "t |= G(diff(t[perception][npc], t[truth][npc2]) < 1);\n", 7,
       8,
       "diff(...) compares an agent's perceived and true states: "
       "diff(trace[perception][a], trace[truth][a])"},
      {"dis_with_one_argument", S + "t |= G(dis(t[ego]) > 1);\n", 7, 8,
       "dis(...) takes two arguments: dis(a, b)"},
      {"unknown_function", S + "t |= G(dist(t[ego], t[truth][npc]) > 1);\n", 7, 8,
       "unknown function 'dist'; did you mean 'dis'?"},
      {"distance_predicate_without_distance", S + "t |= G(stoplineAhead -> speed < 1);\n", 7, 8,
       "'stoplineAhead' needs a distance: write 'stoplineAhead(2)'"},
      {"unknown_dotted_signal", S + "t |= G(trafficLightAhead.colour == red);\n", 7, 8,
       "unknown signal 'trafficLightAhead.colour'; did you mean 'trafficLightAhead.color'?"},
      {"next_with_inverted_interval", S + "t |= X[5, 1] (speed > 1);\n", 7, 7,
       "inverted interval: the lower bound 5 is above the upper bound 1"},
      {"vector_of_four_components", S + "t |= G (vel(t[ego], (1, 2, 3, 4)) > 0);\n", 7, 21,
       "expected a trace projection or a vector (x, y) or (x, y, z) as argument of vel(...), "
       "found a tuple of 4 elements"},
      {"vector_in_the_imu_frame", S + "t |= G (acc(t[ego], IMU (1, 2, 3)) > 0);\n", 7, 21,
       "or (x, y, z) as argument of acc(...), found a position"},
      {"inverted_interval", S + "t |= G[5:1] (speed > 1);\n", 7, 7,
       "inverted interval: the lower bound 5 is above the upper bound 1"},
      {"spec_is_a_number", S + "t |= G 5;\n", 7, 8,
       "expected a formula such as 'dis(a, b) > 1.0', found a number"},

      // ---- known bugs ----
      // Negating a projection that still needs an agent used to dereference an empty optional
      // (Elaborator::unary) and crash; kept as a regression case.
      {"negated_truth_without_agent", S + "t |= G(-t[truth] > 1);\n", 7, 9,
       "name the agent: t[truth][npc1]"},
      // Regression: with the '}' of CreateScenario missing, the parser reads the next statements as
      // more slots and reports "expected ';' after this slot of CreateScenario{...}, found 't'"
      // at 3:6, inside a correct line. The '}' belongs after the last slot (2:47).
      {"missing_close_brace_of_scenario_before_next_statement",
       kEgo + "s = CreateScenario{load(\"m\"); ego; {}; {}; {};\nTrace t = EXE(s);\n" +
           "t |= G(speed > 1);\n",
       2, 47, "expected '}' to close CreateScenario{...}"},
      // Regression: check_not_negative only looks at constants and bare ranges, so an offset
      // written as
      // arithmetic that is negative everywhere ([-9, -8] here) is accepted.
      {"negative_lane_offset_through_arithmetic",
       "p = \"lane_1\"->(range(1, 2) - 10);\ne = AV((p), (\"lane_1\"->9));\n", 1, 16,
       "an arc length along a lane cannot be negative"},
      // Regression: the message gives the bounds in seconds since midnight ("the lower bound 43200
      // is
      // above the upper bound 39600") although the user wrote times of day.
      {"inverted_time_of_day_range", "r = range(12:00, 11:00);\n", 1, 5,
       "the lower bound 12:00 is above the upper bound 11:00"},
  };
}

class MalformedInput : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(MalformedInput, FirstErrorPointsAtTheMistake) {
  const MalformedCase& c = GetParam();
  SCOPED_TRACE(c.name);
  if (!parse_survives(c.text, c.name)) return;  // do not crash the test binary in-process

  SourceFile file("t.avu", c.text);
  ParseResult result = parse(file);
  std::string all = format_diagnostics(file, result.diagnostics);
  EXPECT_FALSE(result.ok()) << "accepted:\n" << c.text;
  const Diagnostic* error = first_error(result.diagnostics);
  ASSERT_NE(error, nullptr) << all;
  EXPECT_EQ(error->location.line, c.line) << all;
  EXPECT_EQ(error->location.column, c.column) << all;
  EXPECT_THAT(error->message, ::testing::HasSubstr(c.message)) << all;
}

INSTANTIATE_TEST_SUITE_P(Malformed, MalformedInput, ::testing::ValuesIn(malformed_cases()),
                         [](const ::testing::TestParamInfo<MalformedCase>& case_info) {
                           return case_info.param.name;
                         });

TEST(MalformedCases, ThereAreEnoughAndNamesAreUnique) {
  std::vector<MalformedCase> cases = malformed_cases();
  EXPECT_GE(cases.size(), 45u);
  std::set<std::string> names;
  for (const MalformedCase& c : cases) EXPECT_TRUE(names.insert(c.name).second) << c.name;
}

// ---- recovery ------------------------------------------------------------------------------

TEST(MalformedRecovery, ThreeIndependentErrorsAreAllReportedInOrder) {
  const std::string text =
      "a = 1;\n"
      "w = Environment(25:00, {});\n"  // 2: lexer
      "b = 2;\n"
      "c = 3;\n"
      "d = 1 2;\n"  // 5: parser
      "e = 4;\n"
      "f = 5;\n"
      "g = range(3, 1);\n"  // 8: elaborator
      "h = a + b + c + e + f;\n";
  if (!parse_survives(text, "three errors")) return;
  SourceFile file("t.avu", text);
  ParseResult result = parse(file);
  std::string all = format_diagnostics(file, result.diagnostics);
  ASSERT_EQ(result.diagnostics.all().size(), 3u) << all;
  std::vector<std::uint32_t> lines;
  for (const Diagnostic& d : result.diagnostics.all()) {
    EXPECT_EQ(d.severity, Severity::error) << all;
    lines.push_back(d.location.line);
  }
  EXPECT_EQ(lines, (std::vector<std::uint32_t>{2, 5, 8})) << all;
}

// Regression: after a syntax error the parser skips to the next ';' outside brackets, counting
// brackets from the start of the statement; an unclosed '(' (or '[', '{') therefore never closes
// and the whole rest of the file is skipped: the errors on lines 8 and 9 are never reported. A ';'
// inside
// '(' or '[' can only end the statement.
TEST(MalformedRecovery, UnclosedParenthesisDoesNotSwallowTheRestOfTheFile) {
  const std::string text =
      "a = 1;\n"
      "w = Environment(25:00, {});\n"  // 2: lexer
      "b = 2;\n"
      "c = 3;\n"
      "d = (1, 2;\n"  // 5: parser, the ')' is missing
      "e = 4;\n"
      "f = 5;\n"
      "g = range(3, 1);\n"  // 8: elaborator
      "h = i + 1;\n";       // 9: elaborator
  if (!parse_survives(text, "unclosed parenthesis")) return;
  SourceFile file("t.avu", text);
  ParseResult result = parse(file);
  std::string all = format_diagnostics(file, result.diagnostics);
  std::vector<std::uint32_t> lines;
  for (const Diagnostic* d : errors_of(result.diagnostics)) lines.push_back(d->location.line);
  EXPECT_EQ(lines, (std::vector<std::uint32_t>{2, 5, 8, 9})) << all;
}

// The lexer, the parser and the elaborator each report in their turn, so errors from different
// phases come out grouped by phase, not by line; all of them must still be there.
TEST(MalformedRecovery, EveryPhaseReportsAfterEarlierPhasesFailed) {
  const std::string text =
      "a = 1;\n"
      "b = range(3, 1);\n"  // 2: elaborator
      "c = 3;\n"
      "d = 4;\n"
      "e = (1, 2;\n"  // 5: parser
      "f = 5;\n"
      "g = 6;\n"
      "h = 99:00;\n";  // 8: lexer
  if (!parse_survives(text, "errors in reverse phase order")) return;
  SourceFile file("t.avu", text);
  ParseResult result = parse(file);
  std::string all = format_diagnostics(file, result.diagnostics);
  ASSERT_EQ(result.diagnostics.all().size(), 3u) << all;
  std::set<std::uint32_t> lines;
  for (const Diagnostic& d : result.diagnostics.all()) lines.insert(d.location.line);
  EXPECT_EQ(lines, (std::set<std::uint32_t>{2, 5, 8})) << all;
}

// Regression: the parser drops a statement it cannot parse, so the elaborator then reports every
// use of the name it defined as "'x' is not defined; did you mean 's'?" — an error the user did not
// make. A name whose definition failed to parse should be known (as erroneous) and stay silent.
TEST(MalformedRecovery, ErrorInsideCreateScenarioDoesNotCascade) {
  const std::string text = kScenario +
                           "x = CreateScenario{load(\"m\"); ego; {npc} {}; {};};\n"  // 7
                           "Trace t2 = EXE(x);\n"
                           "t2 |= G(dis(t2[ego], t2[truth][npc]) > 1);\n"
                           "t |= G(dis(t[ego], t[truth][npc]) > 1);\n";
  if (!parse_survives(text, "error inside CreateScenario")) return;
  SourceFile file("t.avu", text);
  ParseResult result = parse(file);
  std::string all = format_diagnostics(file, result.diagnostics);
  std::vector<const Diagnostic*> errors = errors_of(result.diagnostics);
  ASSERT_EQ(errors.size(), 1u) << all;
  EXPECT_EQ(errors[0]->location.line, 7u);
  EXPECT_EQ(errors[0]->location.column, 41u);
  EXPECT_THAT(errors[0]->message,
              ::testing::HasSubstr("expected ';' after this slot of CreateScenario"));
}

// Regression: the same cascade for a plain assignment.
TEST(MalformedRecovery, AssignmentThatFailedToParseDoesNotMakeItsNameUndefined) {
  const std::string text = "x = 1 2;\ny = x + 1;\n";
  if (!parse_survives(text, "failed assignment")) return;
  SourceFile file("t.avu", text);
  ParseResult result = parse(file);
  std::string all = format_diagnostics(file, result.diagnostics);
  std::vector<const Diagnostic*> errors = errors_of(result.diagnostics);
  ASSERT_EQ(errors.size(), 1u) << all;
  EXPECT_EQ(errors[0]->location.line, 1u);
  EXPECT_EQ(errors[0]->location.column, 6u);
}

// Regression: when the lexer drops a bad token (a bad character, `.5`, `5.`, an unterminated
// string), the parser then reports a second error about the hole it left ("expected ';' ... found
// number '2'", "expected a value, found ';'"). One mistake should give one error: the lexer could
// keep the token (0.5 for `.5`, the string up to the end of the line) or pass an error token that
// the parser skips silently.
TEST(MalformedRecovery, LexerErrorsDoNotCascadeIntoParserErrors) {
  const std::vector<std::string> texts = {"x = 1 @ 2;\n", "x = .5;\n", "x = 5.;\n",
                                          "m = \"abc;\nn = 1;\n"};
  for (const std::string& text : texts) {
    SCOPED_TRACE(text);
    if (!parse_survives(text, text)) continue;
    SourceFile file("t.avu", text);
    ParseResult result = parse(file);
    EXPECT_EQ(errors_of(result.diagnostics).size(), 1u)
        << format_diagnostics(file, result.diagnostics);
  }
}

TEST(MalformedRecovery, StopsAtTheErrorLimit) {
  std::string text;
  for (int i = 1; i <= 100; ++i) text += "x" + std::to_string(i) + " = 1 2;\n";
  if (!parse_survives(text, "100 errors")) return;
  SourceFile file("t.avu", text);
  ParseResult result = parse(file);
  const std::vector<Diagnostic>& all = result.diagnostics.all();
  EXPECT_EQ(result.diagnostics.error_count(), Diagnostics::kErrorLimit);
  ASSERT_EQ(all.size(), Diagnostics::kErrorLimit + 1);
  for (std::size_t i = 0; i < Diagnostics::kErrorLimit; ++i) {
    EXPECT_EQ(all[i].severity, Severity::error);
    EXPECT_EQ(all[i].location.line, i + 1);
  }
  EXPECT_EQ(all.back().severity, Severity::note);
  EXPECT_THAT(all.back().message, ::testing::HasSubstr("too many errors"));
}

// ---- inputs that look malformed but are not, and inputs that must not crash ----------------

// Regression: `[0:60]` and `[30:45]` are lexed as times of day (H:MM) and rejected as invalid
// times;
// `[0:60]` even becomes the interval [1, 0] ("inverted interval"). As interval bounds they are
// plain seconds: G[0:60] is the first minute.
TEST(MalformedLookalike, IntervalWrittenLikeAnInvalidTimeOfDayIsAnInterval) {
  struct Interval {
    std::string written;
    double lower, upper;
  };
  for (const Interval& interval : std::vector<Interval>{{"[0:60]", 0, 60}, {"[30:45]", 30, 45}}) {
    SCOPED_TRACE(interval.written);
    const std::string text = kScenario + "t |= G" + interval.written + " (speed > 1);\n";
    if (!parse_survives(text, interval.written)) continue;
    SourceFile file("t.avu", text);
    ParseResult result = parse(file);
    ASSERT_TRUE(result.ok()) << format_diagnostics(file, result.diagnostics);
    ASSERT_EQ(result.scenario.specs.size(), 1u);
    const Formula& formula = result.scenario.specs[0].formula;
    ASSERT_TRUE(formula.interval.has_value());
    EXPECT_EQ(formula.interval->lower, interval.lower);
    EXPECT_EQ(formula.interval->upper, interval.upper);
  }
}

// Regression: long operator chains build left-deep trees the parser's nesting limit does not count,
// and the elaborator (and, from about 100000 operands, the syntax tree's destructor) recurse once
// per operand: about 500 operands overflow the stack in a Debug build. A chain must either be
// handled or rejected with an error, never crash.
TEST(MalformedPathological, LongOperatorChainsDoNotCrash) {
  auto repeat = [](const std::string& piece, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += piece;
    return out;
  };
  const std::vector<std::pair<std::string, std::string>> texts = {
      {"1000 additions", "x = 1" + repeat(" + 1", 1000) + ";\n"},
      {"1000 conjunctions", kScenario + "t |= G(speed > 1" + repeat(" & speed > 1", 1000) + ");\n"},
      {"1000 pi", "x = 1" + repeat(" pi", 1000) + ";\n"},
      {"1000 indexes", "x = t" + repeat("[ego]", 1000) + ";\n"},
      {"100000 additions", "x = 1" + repeat(" + 1", 100000) + ";\n"},
  };
  for (const auto& [label, text] : texts) {
    SCOPED_TRACE(label);
    parse_survives(text, label);
  }
}

// ---- formatting ----------------------------------------------------------------------------

TEST(MalformedFormat, ShowsPathLineColumnSourceLineAndCaret) {
  SourceFile file("a.avu", "x = 1;\ny = 2 3;\n");
  ParseResult result = parse(file);
  ASSERT_FALSE(result.diagnostics.all().empty());
  std::string text = format_diagnostic(file, result.diagnostics.all()[0]);
  EXPECT_THAT(text, ::testing::StartsWith("a.avu:2:6: error: expected ';' after the assignment"));
  // The source line, then the caret under column 6 (both indented by two spaces).
  EXPECT_THAT(text, ::testing::HasSubstr("\n  y = 2 3;\n  " + std::string(5, ' ') + "^\n"));
}

TEST(MalformedFormat, CaretLinesUpAfterATabAndATypographicQuote) {
  // The tab is one column and is copied into the caret line; the typographic quotes are three
  // bytes each but one column.
  const std::string line =
      "\tm = \xE2\x80\x9C"
      "abc\xE2\x80\x9D x;";
  SourceFile file("a.avu", "x = 1;\n" + line + "\n");
  ParseResult result = parse(file);
  ASSERT_FALSE(result.diagnostics.all().empty());
  const Diagnostic& error = result.diagnostics.all()[0];
  EXPECT_EQ(error.location.line, 2u);
  EXPECT_EQ(error.location.column, 11u);  // just after the closing quote
  std::string text = format_diagnostic(file, error);
  EXPECT_THAT(text, ::testing::StartsWith("a.avu:2:11: error: expected ';' after the assignment"));
  EXPECT_THAT(text, ::testing::HasSubstr("\n  " + line + "\n  \t" + std::string(9, ' ') + "^\n"));
}

TEST(MalformedFormat, UnderlineCountsCharactersNotBytes) {
  // "“été” + 1" is 9 characters and 15 bytes: a caret and 8 tildes.
  const std::string line = "\tm = \xE2\x80\x9C\xC3\xA9t\xC3\xA9\xE2\x80\x9D + 1;";
  SourceFile file("a.avu", line + "\n");
  ParseResult result = parse(file);
  ASSERT_FALSE(result.diagnostics.all().empty());
  const Diagnostic& error = result.diagnostics.all()[0];
  EXPECT_EQ(error.location.column, 6u);
  std::string text = format_diagnostic(file, error);
  EXPECT_THAT(text, ::testing::HasSubstr("\n  \t    ^" + std::string(8, '~') + "\n"));
}

}  // namespace
}  // namespace scenfuzz::avunit
