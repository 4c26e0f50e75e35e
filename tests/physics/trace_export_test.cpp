// trace_csv, trace_json and trace_from_json on a small hand-made trace (three actors, three
// samples, a collision, an undetected perceived sample, two lights): the CSV's shape, quoting and
// perceived columns and vehicle signals; an exact JSON round trip with NaN as null; clear errors
// for bad JSON.
#include "physics/trace/trace_export.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace scenfuzz {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

Trace sample_trace() {
  Trace trace;
  trace.map_name = "crossroads";
  trace.seed = std::numeric_limits<std::uint64_t>::max();
  trace.dt = 0.5;
  trace.time = {0, 0.5, 1.0};
  trace.end = EndReason::collision;

  TraceActor ego;
  ego.name = "ego";
  ego.kind = TraceActorKind::ego;
  ego.category = ActorCategory::car;
  ego.length = 4.7;
  ego.width = 2.06;
  ego.height = 1.5;
  ego.x = {1.0 / 3.0, 5.1, 10.2};
  ego.y = {-5.25, -5.25, -5.2500000000000009};
  ego.heading = {0, 0.001, -0.1};
  ego.speed = {10, 10.2, 9.8};
  ego.acceleration = {0.4, -0.8, -7.5};
  ego.yaw_rate = {0, 0.002, -0.2};
  ego.lane = {0, 0, 1};
  ego.s = {20, 25.1, 0.2};
  ego.signals = {vehicle_signal::left_indicator | vehicle_signal::low_beam, 0,
                 vehicle_signal::brake_lights | vehicle_signal::horn};

  TraceActor npc;
  npc.name = "npc, \"the second\"";
  npc.kind = TraceActorKind::vehicle;
  npc.category = ActorCategory::van;
  npc.length = 5.2;
  npc.width = 2.1;
  npc.height = 2.2;
  npc.x = {15, 14, 12};
  npc.y = {-5.25, -5.25, -5.0};
  npc.heading = {3.14, 3.14, 3.0};
  npc.speed = {2, 2, 0};
  npc.acceleration = {0, 0, -4};
  npc.yaw_rate = {0, 0, 0};
  npc.lane = {2, 2, -1};
  npc.s = {3, 4, 0};
  npc.reversing = {1, 1, 0};  // backing up, then standing
  npc.signals = {0, 0, vehicle_signal::all};

  TraceActor pedestrian;
  pedestrian.name = "ped";
  pedestrian.kind = TraceActorKind::pedestrian;
  pedestrian.category = ActorCategory::pedestrian;
  pedestrian.shape = BodyShape::cylinder;
  pedestrian.length = 0.6;
  pedestrian.width = 0.6;
  pedestrian.height = 1.8;
  pedestrian.x = {-12, -12, -12};
  pedestrian.y = {12, 12.7, 13.4};
  pedestrian.heading = {1.5707963267948966, 1.5707963267948966, 1.5707963267948966};
  pedestrian.speed = {1.4, 1.4, 1.4};
  pedestrian.acceleration = {0, 0, 0};
  pedestrian.yaw_rate = {0, 0, 0};
  pedestrian.lane = {-1, -1, -1};
  pedestrian.s = {0, 0, 0};
  trace.actors = {ego, npc, pedestrian};

  PerceivedActor seen_npc;
  seen_npc.actor = 1;
  seen_npc.detected = {1, 0, 1};
  seen_npc.x = {15.2, nan, 12.1};
  seen_npc.y = {-5.3, nan, -5.1};
  seen_npc.heading = {3.1, nan, 3.0};
  seen_npc.speed = {2.1, nan, 0.1};
  seen_npc.reversing = {1, 0, 0};
  PerceivedActor seen_pedestrian;
  seen_pedestrian.actor = 2;
  seen_pedestrian.detected = {0, 0, 0};
  seen_pedestrian.x = seen_pedestrian.y = seen_pedestrian.heading =
      seen_pedestrian.speed = {nan, nan, nan};
  trace.perceived = {seen_npc, seen_pedestrian};

  trace.lights = {{"signal_ns", {SignalColour::green, SignalColour::yellow, SignalColour::red}},
                  {"signal_ew", {SignalColour::red, SignalColour::red, SignalColour::green}}};
  trace.collisions = {{1.0, 0, 1, {12.5, -3.25}, BodySide::front, BodySide::rear}};
  trace.events = {{TraceEventKind::ego_failure, 0.5, -1, "driver said \"no\"\nthen quit"},
                  {TraceEventKind::collision, 1.0, 0, ""}};
  return trace;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

// One CSV record, RFC 4180 quotes undone (the test data has no line breaks inside fields).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

void expect_same_column(const std::vector<double>& actual, const std::vector<double>& expected,
                        const std::string& what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  for (std::size_t i = 0; i < actual.size(); ++i) {
    if (std::isnan(expected[i]))
      EXPECT_TRUE(std::isnan(actual[i])) << what << "[" << i << "]";
    else
      EXPECT_EQ(actual[i], expected[i]) << what << "[" << i << "]";
  }
}

void expect_equal_traces(const Trace& actual, const Trace& expected) {
  EXPECT_EQ(actual.map_name, expected.map_name);
  EXPECT_EQ(actual.seed, expected.seed);
  EXPECT_EQ(actual.dt, expected.dt);
  EXPECT_EQ(actual.end, expected.end);
  EXPECT_EQ(actual.ego_target.has_value(), expected.ego_target.has_value());
  if (actual.ego_target && expected.ego_target) {
    EXPECT_EQ(actual.ego_target->x, expected.ego_target->x);
    EXPECT_EQ(actual.ego_target->y, expected.ego_target->y);
  }
  EXPECT_EQ(actual.sensing.vehicle_range, expected.sensing.vehicle_range);
  EXPECT_EQ(actual.sensing.pedestrian_range, expected.sensing.pedestrian_range);
  EXPECT_EQ(actual.sensing.limited, expected.sensing.limited);
  expect_same_column(actual.time, expected.time, "time");
  ASSERT_EQ(actual.actors.size(), expected.actors.size());
  for (std::size_t i = 0; i < actual.actors.size(); ++i) {
    const TraceActor& a = actual.actors[i];
    const TraceActor& e = expected.actors[i];
    EXPECT_EQ(a.name, e.name);
    EXPECT_EQ(a.kind, e.kind);
    EXPECT_EQ(a.category, e.category);
    EXPECT_EQ(a.shape, e.shape);
    EXPECT_EQ(a.length, e.length);
    EXPECT_EQ(a.width, e.width);
    EXPECT_EQ(a.height, e.height);
    expect_same_column(a.x, e.x, e.name + ".x");
    expect_same_column(a.y, e.y, e.name + ".y");
    expect_same_column(a.heading, e.heading, e.name + ".heading");
    expect_same_column(a.speed, e.speed, e.name + ".speed");
    expect_same_column(a.acceleration, e.acceleration, e.name + ".acceleration");
    expect_same_column(a.yaw_rate, e.yaw_rate, e.name + ".yaw_rate");
    EXPECT_EQ(a.lane, e.lane);
    expect_same_column(a.s, e.s, e.name + ".s");
    for (std::size_t k = 0; k < actual.time.size(); ++k)
      EXPECT_EQ(reversing_at(a.reversing, k), reversing_at(e.reversing, k))
          << e.name << ".reversing[" << k << "]";
    EXPECT_EQ(a.signals, e.signals) << e.name;
  }
  ASSERT_EQ(actual.perceived.size(), expected.perceived.size());
  for (std::size_t i = 0; i < actual.perceived.size(); ++i) {
    const PerceivedActor& a = actual.perceived[i];
    const PerceivedActor& e = expected.perceived[i];
    EXPECT_EQ(a.actor, e.actor);
    EXPECT_EQ(a.detected, e.detected);
    expect_same_column(a.x, e.x, "perceived.x");
    expect_same_column(a.y, e.y, "perceived.y");
    expect_same_column(a.heading, e.heading, "perceived.heading");
    expect_same_column(a.speed, e.speed, "perceived.speed");
    for (std::size_t k = 0; k < actual.time.size(); ++k)
      EXPECT_EQ(reversing_at(a.reversing, k), reversing_at(e.reversing, k))
          << "perceived.reversing[" << k << "]";
  }
  ASSERT_EQ(actual.lights.size(), expected.lights.size());
  for (std::size_t i = 0; i < actual.lights.size(); ++i) {
    EXPECT_EQ(actual.lights[i].id, expected.lights[i].id);
    EXPECT_EQ(actual.lights[i].colour, expected.lights[i].colour);
  }
  ASSERT_EQ(actual.collisions.size(), expected.collisions.size());
  for (std::size_t i = 0; i < actual.collisions.size(); ++i) {
    const Collision& a = actual.collisions[i];
    const Collision& e = expected.collisions[i];
    EXPECT_EQ(a.time, e.time);
    EXPECT_EQ(a.first, e.first);
    EXPECT_EQ(a.second, e.second);
    EXPECT_EQ(a.point, e.point);
    EXPECT_EQ(a.first_side, e.first_side);
    EXPECT_EQ(a.second_side, e.second_side);
  }
  ASSERT_EQ(actual.events.size(), expected.events.size());
  for (std::size_t i = 0; i < actual.events.size(); ++i) {
    EXPECT_EQ(actual.events[i].kind, expected.events[i].kind);
    EXPECT_EQ(actual.events[i].time, expected.events[i].time);
    EXPECT_EQ(actual.events[i].collision, expected.events[i].collision);
    EXPECT_EQ(actual.events[i].message, expected.events[i].message);
  }
}

// The message of the std::runtime_error that reading `json` throws, or "" when none is thrown.
std::string read_error(const std::string& json) {
  try {
    trace_from_json(json);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(TraceExport, FindActorAndNames) {
  const Trace trace = sample_trace();
  EXPECT_EQ(trace.find_actor("ped"), ActorId{2});
  EXPECT_EQ(trace.find_actor("ego"), kEgo);
  EXPECT_EQ(trace.find_actor("nobody"), std::nullopt);
  EXPECT_EQ(trace_actor_kind_name(TraceActorKind::pedestrian), "pedestrian");
  EXPECT_EQ(end_reason_name(EndReason::target_reached), "target_reached");
  EXPECT_EQ(signal_colour_name(SignalColour::yellow), "yellow");
}

TEST(TraceExport, CsvHasAHeaderAndOneRowPerSampleAndActor) {
  const std::vector<std::string> lines = lines_of(trace_csv(sample_trace()));
  ASSERT_EQ(lines.size(), 1u + 3 * 3);
  EXPECT_EQ(lines[0],
            "time,actor,kind,x,y,heading,speed,acceleration,yaw_rate,lane,s,reversing,"
            "perceived_detected,perceived_x,perceived_y,perceived_heading,perceived_speed,"
            "perceived_reversing,signals");
  for (std::size_t i = 1; i < lines.size(); ++i)
    EXPECT_EQ(csv_fields(lines[i]).size(), 19u) << lines[i];
  // Samples in time order, actors in id order within a sample.
  EXPECT_EQ(csv_fields(lines[1])[1], "ego");
  EXPECT_EQ(csv_fields(lines[3])[1], "ped");
  EXPECT_EQ(csv_fields(lines[4])[0], "0.5");
  EXPECT_EQ(csv_fields(lines[4])[2], "ego");
}

TEST(TraceExport, CsvQuotesNamesWithCommasAndQuotes) {
  const std::vector<std::string> lines = lines_of(trace_csv(sample_trace()));
  EXPECT_EQ(lines[2].rfind("0,\"npc, \"\"the second\"\"\",vehicle,", 0), 0u) << lines[2];
  EXPECT_EQ(csv_fields(lines[2])[1], "npc, \"the second\"");
}

TEST(TraceExport, CsvNumbersReadBackExactly) {
  const Trace trace = sample_trace();
  const std::vector<std::string> lines = lines_of(trace_csv(trace));
  EXPECT_EQ(std::stod(csv_fields(lines[1])[3]), trace.actors[0].x[0]);  // 1/3
  EXPECT_EQ(std::stod(csv_fields(lines[7])[4]), trace.actors[0].y[2]);  // one ulp off -5.25
  EXPECT_EQ(csv_fields(lines[1])[3].size(), std::string("0.3333333333333333").size());
}

TEST(TraceExport, CsvPerceivedColumnsAreEmptyForTheEgoAndUndetectedSamples) {
  const std::vector<std::string> lines = lines_of(trace_csv(sample_trace()));
  const std::vector<std::string> ego = csv_fields(lines[1]);
  for (std::size_t column = 12; column < 18; ++column) EXPECT_EQ(ego[column], "") << column;

  const std::vector<std::string> detected = csv_fields(lines[2]);  // npc at t = 0
  EXPECT_EQ(detected[12], "1");
  EXPECT_EQ(detected[13], "15.2");
  EXPECT_EQ(detected[14], "-5.3");
  EXPECT_EQ(detected[15], "3.1");
  EXPECT_EQ(detected[16], "2.1");
  EXPECT_EQ(detected[17], "1");

  const std::vector<std::string> missed = csv_fields(lines[5]);  // npc at t = 0.5
  EXPECT_EQ(missed[1], "npc, \"the second\"");
  EXPECT_EQ(missed[12], "0");
  for (std::size_t column = 13; column < 18; ++column) EXPECT_EQ(missed[column], "") << column;
}

TEST(TraceExport, CsvSaysWhereAnActorReverses) {
  const std::vector<std::string> lines = lines_of(trace_csv(sample_trace()));
  EXPECT_EQ(csv_fields(lines[1])[11], "0");  // the ego at t = 0
  EXPECT_EQ(csv_fields(lines[2])[11], "1");  // the npc backing up at t = 0
  EXPECT_EQ(csv_fields(lines[8])[11], "0");  // and standing at t = 1
  EXPECT_EQ(csv_fields(lines[3])[11], "0");  // the pedestrian, whose column is empty
}

TEST(TraceExport, CsvNamesTheVehicleSignalsOn) {
  const std::vector<std::string> lines = lines_of(trace_csv(sample_trace()));
  EXPECT_EQ(csv_fields(lines[1])[18], "left_indicator|low_beam");  // the ego at t = 0
  EXPECT_EQ(csv_fields(lines[4])[18], "");                         // and at t = 0.5
  EXPECT_EQ(csv_fields(lines[7])[18], "horn|brake_lights");        // and at t = 1
  EXPECT_EQ(csv_fields(lines[8])[18],
            "left_indicator|right_indicator|hazard_lights|horn|low_beam|high_beam|fog_lights|"
            "wipers|brake_lights");
  EXPECT_EQ(csv_fields(lines[3])[18], "");  // the pedestrian shows none
}

TEST(TraceExport, JsonSignalsAreBitSetsAndOptional) {
  const std::string json = trace_json(sample_trace());
  EXPECT_NE(json.find("\"signals\":[17,0,264]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"signals\":[0,0,511]"), std::string::npos);
  // As traces written before signals were recorded: none shown.
  const Trace old =
      trace_from_json(std::regex_replace(json, std::regex(R"(,"signals":\[[0-9,]*\])"), ""));
  for (const TraceActor& actor : old.actors) EXPECT_TRUE(actor.signals.empty()) << actor.name;
  EXPECT_EQ(read_error(replaced(json, "[0,0,511]", "[0,0,512]")),
            "trace JSON: actors[1].samples.signals[2]: signal bits 512 out of range (0 to 511)");
  EXPECT_EQ(read_error(replaced(json, "[0,0,511]", "[0,0]")),
            "trace JSON: actors[1].samples.signals: has 2 entries, expected one per sample (3)");
}

TEST(TraceExport, CsvLanesPrintAsMapIdsWhenGiven) {
  const Trace trace = sample_trace();
  const std::vector<std::string> by_index = lines_of(trace_csv(trace));
  EXPECT_EQ(csv_fields(by_index[7])[9], "1");  // ego at t = 1
  EXPECT_EQ(csv_fields(by_index[7])[10], "0.2");
  EXPECT_EQ(csv_fields(by_index[8])[9], "");  // npc off the lanes: no lane, no s
  EXPECT_EQ(csv_fields(by_index[8])[10], "");

  const std::vector<std::string> ids{"west_in_0", "west_in_1", "lane, odd"};
  const std::vector<std::string> by_id = lines_of(trace_csv(trace, ids));
  EXPECT_EQ(csv_fields(by_id[7])[9], "west_in_1");
  EXPECT_EQ(csv_fields(by_id[2])[9], "lane, odd");
  EXPECT_NE(by_id[2].find(",\"lane, odd\","), std::string::npos);

  const std::vector<std::string> too_few{"west_in_0"};
  EXPECT_THROW(trace_csv(trace, too_few), std::out_of_range);
}

TEST(TraceExport, JsonRoundTripGivesAnEqualTrace) {
  const Trace trace = sample_trace();
  const std::string json = trace_json(trace);
  expect_equal_traces(trace_from_json(json), trace);
  // And the reloaded trace writes the same text.
  EXPECT_EQ(trace_json(trace_from_json(json)), json);
}

TEST(TraceExport, JsonKeepsTheEgosTargetAndItsSensing) {
  Trace trace = sample_trace();
  trace.ego_target = MapPoint{412.5, -5.25};
  trace.sensing = {38.5, 21.25, true};
  const std::string json = trace_json(trace);
  EXPECT_NE(json.find("\"ego_target\":[412.5,-5.25]"), std::string::npos) << json.substr(0, 300);
  EXPECT_NE(json.find("\"limited\":true"), std::string::npos);
  expect_equal_traces(trace_from_json(json), trace);
  // Written before they were recorded: no target, sensing not recorded.
  const std::string older =
      std::regex_replace(json, std::regex(R"("ego_target":\[[^\]]*\],"sensing":\{[^}]*\},)"), "");
  ASSERT_EQ(older.find("sensing"), std::string::npos);
  const Trace read = trace_from_json(older);
  EXPECT_FALSE(read.ego_target);
  EXPECT_EQ(read.sensing.vehicle_range, 0);
}

TEST(TraceExport, JsonRoundTripOfAnEmptyTrace) {
  Trace trace;
  trace.actors.push_back({});
  expect_equal_traces(trace_from_json(trace_json(trace)), trace);
}

TEST(TraceExport, JsonWithoutReversingColumnsReadsAsNeverReversing) {
  // As traces written before the columns existed.
  const std::string json =
      std::regex_replace(trace_json(sample_trace()), std::regex(R"(,"reversing":\[[a-z,]*\])"), "");
  ASSERT_EQ(json.find("reversing"), std::string::npos);
  const Trace trace = trace_from_json(json);
  for (const TraceActor& actor : trace.actors) EXPECT_TRUE(actor.reversing.empty()) << actor.name;
  for (const PerceivedActor& seen : trace.perceived) EXPECT_TRUE(seen.reversing.empty());
  EXPECT_NE(read_error(replaced(trace_json(sample_trace()), "[true,true,false]", "[1,1,0]"))
                .find("actors[1].samples.reversing[0]: expected true or false"),
            std::string::npos);
}

TEST(TraceExport, JsonWritesNaNAsNullAndColumnsAsArrays) {
  const std::string json = trace_json(sample_trace());
  EXPECT_NE(json.find("[15.2,null,12.1]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"detected\":[true,false,true]"), std::string::npos);
  EXPECT_NE(json.find("\"colour\":[\"green\",\"yellow\",\"red\"]"), std::string::npos);
  EXPECT_NE(json.find("\"point\":[12.5,-3.25]"), std::string::npos);
  EXPECT_NE(json.find("\"first_side\":\"front\""), std::string::npos);
  EXPECT_NE(json.find("\"time\":[0.0,0.5,1.0]"), std::string::npos);
  EXPECT_EQ(json.find("NaN"), std::string::npos);
  EXPECT_EQ(json.find("nan"), std::string::npos);
}

TEST(TraceExport, MalformedJsonIsAClearError) {
  EXPECT_NE(read_error("{\"map\": ").find("trace JSON: not valid JSON"), std::string::npos);
  EXPECT_NE(read_error("[1, 2]").find("top level: expected an object"), std::string::npos);
  EXPECT_NE(read_error("{}").find("missing field \"format\""), std::string::npos);
  const std::string json = trace_json(sample_trace());
  EXPECT_NE(read_error(replaced(json, "\"version\":1", "\"version\":2"))
                .find("version 2 is not supported"),
            std::string::npos);
}

TEST(TraceExport, MissingOrMistypedFieldsNameTheirPlace) {
  const std::string json = trace_json(sample_trace());
  EXPECT_EQ(read_error(replaced(json, "\"yaw_rate\":", "\"yaw_rat\":")),
            "trace JSON: actors[0].samples: missing field \"yaw_rate\"");
  EXPECT_EQ(read_error(replaced(json, "\"dt\":0.5", "\"dt\":\"fast\"")),
            "trace JSON: dt: expected a number");
  EXPECT_EQ(read_error(replaced(json, "[15.2,null,12.1]", "[15.2,null]")),
            "trace JSON: perceived[0].x: has 2 entries, expected one per sample (3)");
  EXPECT_EQ(read_error(replaced(json, "[15.2,null,12.1]", "[15.2,\"x\",12.1]")),
            "trace JSON: perceived[0].x[1]: expected a number or null");
  EXPECT_EQ(read_error(replaced(json, "\"second_side\":\"rear\"", "\"second_side\":\"back\"")),
            "trace JSON: collisions[0].second_side: unknown name \"back\"; expected one of "
            "front, rear, left, right");
  EXPECT_EQ(read_error(replaced(json, "\"second\":1", "\"second\":7")),
            "trace JSON: collisions[0].second: actor id 7 out of range (the trace has 3 actors)");
  EXPECT_EQ(read_error(replaced(json, "\"collision\":0", "\"collision\":4")),
            "trace JSON: events[1].collision: collision index 4 out of range (the trace has 1 "
            "collisions)");
  EXPECT_EQ(read_error(replaced(json, "\"kind\":\"vehicle\"", "\"kind\":\"tank\"")),
            "trace JSON: actors[1].kind: unknown name \"tank\"; expected one of ego, vehicle, "
            "pedestrian, obstacle");
}

}  // namespace
}  // namespace scenfuzz
