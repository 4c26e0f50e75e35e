// trace_csv, trace_json and trace_from_json. JSON keeps the trace's columns as arrays, so a
// minute-long run of a few actors stays a few hundred kB and reads back exactly: nlohmann::json
// writes doubles in their shortest round-trip form.
#include "physics/trace/trace_export.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "lang/demand.hpp"
#include "physics/actors/vehicle_signal_names.hpp"

namespace scenfuzz {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;  // written in the documented order, for people reading it

constexpr int trace_format_version = 1;
constexpr std::string_view trace_format_name = "scenfuzz-trace";

constexpr std::array all_actor_kinds{TraceActorKind::ego, TraceActorKind::vehicle,
                                     TraceActorKind::pedestrian, TraceActorKind::obstacle};
constexpr std::array all_categories{ActorCategory::car,      ActorCategory::van,
                                    ActorCategory::bus,      ActorCategory::truck,
                                    ActorCategory::bicycle,  ActorCategory::motorbicycle,
                                    ActorCategory::tricycle, ActorCategory::pedestrian};
constexpr std::array all_shapes{BodyShape::box, BodyShape::cylinder, BodyShape::sphere,
                                BodyShape::cone};
constexpr std::array all_colours{SignalColour::red, SignalColour::yellow, SignalColour::green};
constexpr std::array all_sides{BodySide::front, BodySide::rear, BodySide::left, BodySide::right};
constexpr std::array all_event_kinds{TraceEventKind::collision, TraceEventKind::target_reached,
                                     TraceEventKind::timeout, TraceEventKind::ego_failure,
                                     TraceEventKind::end_condition};
constexpr std::array all_end_reasons{EndReason::duration, EndReason::target_reached,
                                     EndReason::collision, EndReason::ego_failure,
                                     EndReason::end_condition};

std::string_view body_shape_name(BodyShape shape) {
  switch (shape) {
    case BodyShape::box: return "box";
    case BodyShape::cylinder: return "cylinder";
    case BodyShape::sphere: return "sphere";
    case BodyShape::cone: return "cone";
  }
  return "unknown";
}

std::string_view event_kind_name(TraceEventKind kind) {
  switch (kind) {
    case TraceEventKind::collision: return "collision";
    case TraceEventKind::target_reached: return "target_reached";
    case TraceEventKind::timeout: return "timeout";
    case TraceEventKind::ego_failure: return "ego_failure";
    case TraceEventKind::end_condition: return "end_condition";
  }
  return "unknown";
}

std::string_view category_name(ActorCategory category) { return actor_class(category).name; }

// ---- CSV ----

// Empty for NaN: a spreadsheet reads an empty cell as missing, not as text.
void append_csv_number(std::string& out, double value) {
  if (std::isnan(value)) return;
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out.append(buffer.data(), result.ptr);
}

void append_csv_text(std::string& out, std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) {
    out += text;
    return;
  }
  out += '"';
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

void append_csv_lane(std::string& out, std::int32_t lane, std::span<const std::string> lane_ids) {
  if (lane < 0) return;
  if (lane_ids.empty()) {
    out += std::to_string(lane);
    return;
  }
  const auto index = static_cast<std::size_t>(lane);
  if (index >= lane_ids.size())
    throw std::out_of_range("trace CSV: lane index " + std::to_string(lane) +
                            " is not among the map's " + std::to_string(lane_ids.size()) +
                            " lanes");
  append_csv_text(out, lane_ids[index]);
}

// ---- JSON writing ----

// One boolean per sample (an empty column: all false, as it means).
ordered_json reversing_json(const std::vector<std::uint8_t>& reversing, std::size_t sample_count) {
  ordered_json flags = ordered_json::array();
  for (std::size_t i = 0; i < sample_count; ++i) flags.push_back(reversing_at(reversing, i));
  return flags;
}

ordered_json actor_json(const TraceActor& actor) {
  ordered_json samples = ordered_json::object();
  samples["x"] = actor.x;
  samples["y"] = actor.y;
  samples["heading"] = actor.heading;
  samples["speed"] = actor.speed;
  samples["acceleration"] = actor.acceleration;
  samples["yaw_rate"] = actor.yaw_rate;
  samples["lane"] = actor.lane;
  samples["s"] = actor.s;
  samples["reversing"] = reversing_json(actor.reversing, actor.x.size());
  // Bit sets (vehicle_signals.hpp), only for an actor that shows signals at all.
  if (!actor.signals.empty()) samples["signals"] = actor.signals;
  ordered_json written{{"name", actor.name},
                       {"kind", trace_actor_kind_name(actor.kind)},
                       {"category", category_name(actor.category)},
                       {"shape", body_shape_name(actor.shape)},
                       {"length", actor.length},
                       {"width", actor.width},
                       {"height", actor.height}};
  // Only an actor that came or went during the run (background traffic) says when it was there.
  const std::size_t n = actor.x.size();
  if (!present_throughout(actor, n))
    written["present"] = {std::min(actor.present_from, n), std::min(actor.present_until, n)};
  written["samples"] = std::move(samples);
  return written;
}

ordered_json perceived_json(const PerceivedActor& perceived) {
  ordered_json detected = ordered_json::array();
  for (const std::uint8_t flag : perceived.detected) detected.push_back(flag != 0);
  return ordered_json{{"actor", perceived.actor},
                      {"detected", std::move(detected)},
                      {"x", perceived.x},
                      {"y", perceived.y},
                      {"heading", perceived.heading},
                      {"speed", perceived.speed},
                      {"reversing", reversing_json(perceived.reversing, perceived.x.size())}};
}

ordered_json light_json(const TraceLight& light) {
  ordered_json colours = ordered_json::array();
  for (const SignalColour colour : light.colour) colours.push_back(signal_colour_name(colour));
  return ordered_json{{"id", light.id}, {"colour", std::move(colours)}};
}

ordered_json collision_json(const Collision& collision) {
  return ordered_json{{"time", collision.time},
                      {"first", collision.first},
                      {"second", collision.second},
                      {"point", ordered_json::array({collision.point.x, collision.point.y})},
                      {"first_side", body_side_name(collision.first_side)},
                      {"second_side", body_side_name(collision.second_side)}};
}

ordered_json event_json(const TraceEvent& event) {
  return ordered_json{{"kind", event_kind_name(event.kind)},
                      {"time", event.time},
                      {"collision", event.collision},
                      {"message", event.message}};
}

// ---- JSON reading ----

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw std::runtime_error("trace JSON: " + where + ": " + what);
}

std::string member_path(const std::string& where, std::string_view key) {
  return where.empty() ? std::string(key) : where + "." + std::string(key);
}

std::string element_path(const std::string& where, std::size_t index) {
  return where + "[" + std::to_string(index) + "]";
}

const json& require_object(const json& value, const std::string& where) {
  if (!value.is_object()) fail(where, "expected an object");
  return value;
}

const json& require_array(const json& value, const std::string& where) {
  if (!value.is_array()) fail(where, "expected an array");
  return value;
}

const json& member(const json& object, std::string_view key, const std::string& where) {
  const auto found = object.find(key);
  if (found == object.end())
    fail(where.empty() ? "top level" : where, "missing field \"" + std::string(key) + "\"");
  return *found;
}

double read_number(const json& value, const std::string& where) {
  if (!value.is_number()) fail(where, "expected a number");
  return value.get<double>();
}

double read_number_or_null(const json& value, const std::string& where) {
  if (value.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!value.is_number()) fail(where, "expected a number or null");
  return value.get<double>();
}

std::int64_t read_integer(const json& value, const std::string& where) {
  if (value.is_number_unsigned()) {
    if (value.get<std::uint64_t>() >
        static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
      fail(where, "integer too large");
    return static_cast<std::int64_t>(value.get<std::uint64_t>());
  }
  if (!value.is_number_integer()) fail(where, "expected an integer");
  return value.get<std::int64_t>();
}

std::string read_string(const json& value, const std::string& where) {
  if (!value.is_string()) fail(where, "expected a string");
  return value.get<std::string>();
}

template <typename Enum, std::size_t count, typename NameOf>
Enum read_enum(const json& value, const std::string& where,
               const std::array<Enum, count>& candidates, NameOf name_of) {
  const std::string text = read_string(value, where);
  std::string accepted;
  for (const Enum candidate : candidates) {
    if (name_of(candidate) == text) return candidate;
    if (!accepted.empty()) accepted += ", ";
    accepted += name_of(candidate);
  }
  fail(where, "unknown name \"" + text + "\"; expected one of " + accepted);
}

ActorId read_actor_id(const json& value, const std::string& where, std::size_t actor_count) {
  const std::int64_t id = read_integer(value, where);
  if (id < 0 || static_cast<std::uint64_t>(id) >= actor_count)
    fail(where, "actor id " + std::to_string(id) + " out of range (the trace has " +
                    std::to_string(actor_count) + " actors)");
  return static_cast<ActorId>(id);
}

// The array at object[key], which must hold one entry per sample.
const json& read_column(const json& object, std::string_view key, const std::string& where,
                        std::size_t sample_count) {
  const std::string path = member_path(where, key);
  const json& column = require_array(member(object, key, where), path);
  if (column.size() != sample_count)
    fail(path, "has " + std::to_string(column.size()) + " entries, expected one per sample (" +
                   std::to_string(sample_count) + ")");
  return column;
}

std::vector<double> read_number_column(const json& object, std::string_view key,
                                       const std::string& where, std::size_t sample_count) {
  const json& column = read_column(object, key, where, sample_count);
  const std::string path = member_path(where, key);
  std::vector<double> values;
  values.reserve(column.size());
  for (std::size_t i = 0; i < column.size(); ++i)
    values.push_back(read_number_or_null(column[i], element_path(path, i)));
  return values;
}

std::vector<std::uint8_t> read_flag_column(const json& object, std::string_view key,
                                           const std::string& where, std::size_t sample_count) {
  const json& column = read_column(object, key, where, sample_count);
  const std::string path = member_path(where, key);
  std::vector<std::uint8_t> flags;
  flags.reserve(column.size());
  for (std::size_t i = 0; i < column.size(); ++i) {
    if (!column[i].is_boolean()) fail(element_path(path, i), "expected true or false");
    flags.push_back(column[i].get<bool>() ? 1 : 0);
  }
  return flags;
}

// Traces written before the column existed have none: nothing in them reverses.
std::vector<std::uint8_t> read_reversing_column(const json& object, const std::string& where,
                                                std::size_t sample_count) {
  if (!object.contains("reversing")) return {};
  return read_flag_column(object, "reversing", where, sample_count);
}

// Optional, as traces written before signals were recorded have none: then none were shown.
std::vector<VehicleSignals> read_signals_column(const json& object, const std::string& where,
                                                std::size_t sample_count) {
  if (!object.contains("signals")) return {};
  const json& column = read_column(object, "signals", where, sample_count);
  const std::string path = member_path(where, "signals");
  std::vector<VehicleSignals> values;
  values.reserve(column.size());
  for (std::size_t i = 0; i < column.size(); ++i) {
    const std::int64_t bits = read_integer(column[i], element_path(path, i));
    if (bits < 0 || bits > vehicle_signal::all)
      fail(element_path(path, i), "signal bits " + std::to_string(bits) + " out of range (0 to " +
                                      std::to_string(vehicle_signal::all) + ")");
    values.push_back(static_cast<VehicleSignals>(bits));
  }
  return values;
}

std::vector<std::int32_t> read_lane_column(const json& object, const std::string& where,
                                           std::size_t sample_count) {
  const json& column = read_column(object, "lane", where, sample_count);
  const std::string path = member_path(where, "lane");
  std::vector<std::int32_t> values;
  values.reserve(column.size());
  for (std::size_t i = 0; i < column.size(); ++i) {
    const std::int64_t lane = read_integer(column[i], element_path(path, i));
    if (lane < -1 || lane > std::numeric_limits<std::int32_t>::max())
      fail(element_path(path, i), "lane index " + std::to_string(lane) + " out of range");
    values.push_back(static_cast<std::int32_t>(lane));
  }
  return values;
}

// "present": [from, until], samples with from <= until <= the sample count; without it the actor
// was there throughout.
void read_presence(const json& actor_value, const std::string& where, std::size_t sample_count,
                   TraceActor& actor) {
  if (!actor_value.contains("present")) return;
  const std::string path = member_path(where, "present");
  const json& interval = require_array(actor_value["present"], path);
  if (interval.size() != 2) fail(path, "expected [from, until]");
  const std::int64_t from = read_integer(interval[0], element_path(path, 0));
  const std::int64_t until = read_integer(interval[1], element_path(path, 1));
  if (from < 0 || from > until || static_cast<std::uint64_t>(until) > sample_count)
    fail(path, "expected 0 <= from <= until <= " + std::to_string(sample_count));
  actor.present_from = static_cast<std::size_t>(from);
  actor.present_until = static_cast<std::size_t>(until);
}

TraceActor read_actor(const json& value, const std::string& where, std::size_t sample_count) {
  require_object(value, where);
  TraceActor actor;
  actor.name = read_string(member(value, "name", where), member_path(where, "name"));
  actor.kind = read_enum(member(value, "kind", where), member_path(where, "kind"), all_actor_kinds,
                         trace_actor_kind_name);
  actor.category = read_enum(member(value, "category", where), member_path(where, "category"),
                             all_categories, category_name);
  actor.shape = read_enum(member(value, "shape", where), member_path(where, "shape"), all_shapes,
                          body_shape_name);
  actor.length = read_number(member(value, "length", where), member_path(where, "length"));
  actor.width = read_number(member(value, "width", where), member_path(where, "width"));
  actor.height = read_number(member(value, "height", where), member_path(where, "height"));
  const std::string samples_path = member_path(where, "samples");
  const json& samples = require_object(member(value, "samples", where), samples_path);
  actor.x = read_number_column(samples, "x", samples_path, sample_count);
  actor.y = read_number_column(samples, "y", samples_path, sample_count);
  actor.heading = read_number_column(samples, "heading", samples_path, sample_count);
  actor.speed = read_number_column(samples, "speed", samples_path, sample_count);
  actor.acceleration = read_number_column(samples, "acceleration", samples_path, sample_count);
  actor.yaw_rate = read_number_column(samples, "yaw_rate", samples_path, sample_count);
  actor.lane = read_lane_column(samples, samples_path, sample_count);
  actor.s = read_number_column(samples, "s", samples_path, sample_count);
  actor.reversing = read_reversing_column(samples, samples_path, sample_count);
  actor.signals = read_signals_column(samples, samples_path, sample_count);
  read_presence(value, where, sample_count, actor);
  return actor;
}

PerceivedActor read_perceived(const json& value, const std::string& where, std::size_t sample_count,
                              std::size_t actor_count) {
  require_object(value, where);
  PerceivedActor perceived;
  perceived.actor =
      read_actor_id(member(value, "actor", where), member_path(where, "actor"), actor_count);
  perceived.detected = read_flag_column(value, "detected", where, sample_count);
  perceived.x = read_number_column(value, "x", where, sample_count);
  perceived.y = read_number_column(value, "y", where, sample_count);
  perceived.heading = read_number_column(value, "heading", where, sample_count);
  perceived.speed = read_number_column(value, "speed", where, sample_count);
  perceived.reversing = read_reversing_column(value, where, sample_count);
  return perceived;
}

TraceLight read_light(const json& value, const std::string& where, std::size_t sample_count) {
  require_object(value, where);
  TraceLight light;
  light.id = read_string(member(value, "id", where), member_path(where, "id"));
  const json& colours = read_column(value, "colour", where, sample_count);
  for (std::size_t i = 0; i < colours.size(); ++i)
    light.colour.push_back(read_enum(colours[i], element_path(member_path(where, "colour"), i),
                                     all_colours, signal_colour_name));
  return light;
}

Collision read_collision(const json& value, const std::string& where, std::size_t actor_count) {
  require_object(value, where);
  Collision collision;
  collision.time = read_number(member(value, "time", where), member_path(where, "time"));
  collision.first =
      read_actor_id(member(value, "first", where), member_path(where, "first"), actor_count);
  collision.second =
      read_actor_id(member(value, "second", where), member_path(where, "second"), actor_count);
  const std::string point_path = member_path(where, "point");
  const json& point = require_array(member(value, "point", where), point_path);
  if (point.size() != 2) fail(point_path, "expected [x, y]");
  collision.point = {read_number(point[0], element_path(point_path, 0)),
                     read_number(point[1], element_path(point_path, 1))};
  collision.first_side = read_enum(member(value, "first_side", where),
                                   member_path(where, "first_side"), all_sides, body_side_name);
  collision.second_side = read_enum(member(value, "second_side", where),
                                    member_path(where, "second_side"), all_sides, body_side_name);
  return collision;
}

TraceEvent read_event(const json& value, const std::string& where, std::size_t collision_count) {
  require_object(value, where);
  TraceEvent event;
  event.kind = read_enum(member(value, "kind", where), member_path(where, "kind"), all_event_kinds,
                         event_kind_name);
  event.time = read_number(member(value, "time", where), member_path(where, "time"));
  const std::string collision_path = member_path(where, "collision");
  event.collision = read_integer(member(value, "collision", where), collision_path);
  if (event.collision < -1 ||
      (event.collision >= 0 && static_cast<std::uint64_t>(event.collision) >= collision_count))
    fail(collision_path, "collision index " + std::to_string(event.collision) +
                             " out of range (the trace has " + std::to_string(collision_count) +
                             " collisions)");
  event.message = read_string(member(value, "message", where), member_path(where, "message"));
  return event;
}

// Every column has one entry per sample: what the simulation guarantees.
[[maybe_unused]] bool columns_complete(const Trace& trace) {
  const std::size_t n = trace.sample_count();
  const bool actors = std::ranges::all_of(trace.actors, [n](const TraceActor& actor) {
    return actor.x.size() == n && actor.y.size() == n && actor.heading.size() == n &&
           actor.speed.size() == n && actor.acceleration.size() == n &&
           actor.yaw_rate.size() == n && actor.lane.size() == n && actor.s.size() == n &&
           (actor.reversing.empty() || actor.reversing.size() == n) &&
           (actor.signals.empty() || actor.signals.size() == n);
  });
  return actors && std::ranges::all_of(trace.perceived, [n](const PerceivedActor& perceived) {
           return perceived.detected.size() == n && perceived.x.size() == n &&
                  perceived.y.size() == n && perceived.heading.size() == n &&
                  perceived.speed.size() == n &&
                  (perceived.reversing.empty() || perceived.reversing.size() == n);
         });
}

}  // namespace

std::string trace_csv(const Trace& trace, std::span<const std::string> lane_ids) {
  SCENFUZZ_DEMAND(columns_complete(trace));
  std::vector<const PerceivedActor*> perceived_by_actor(trace.actors.size(), nullptr);
  for (const PerceivedActor& perceived : trace.perceived)
    if (perceived.actor < perceived_by_actor.size())
      perceived_by_actor[perceived.actor] = &perceived;

  std::string out =
      "time,actor,kind,x,y,heading,speed,acceleration,yaw_rate,lane,s,reversing,"
      "perceived_detected,perceived_x,perceived_y,perceived_heading,perceived_speed,"
      "perceived_reversing,signals\n";
  out.reserve(out.size() + trace.sample_count() * trace.actors.size() * 160);
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    for (std::size_t id = 0; id < trace.actors.size(); ++id) {
      const TraceActor& actor = trace.actors[id];
      if (!present_at(actor, i)) continue;  // a flow vehicle off the map has no row
      append_csv_number(out, trace.time[i]);
      out += ',';
      append_csv_text(out, actor.name);
      out += ',';
      out += trace_actor_kind_name(actor.kind);
      for (const std::vector<double>* column : {&actor.x, &actor.y, &actor.heading, &actor.speed,
                                                &actor.acceleration, &actor.yaw_rate}) {
        out += ',';
        append_csv_number(out, (*column)[i]);
      }
      out += ',';
      append_csv_lane(out, actor.lane[i], lane_ids);
      out += ',';
      if (actor.lane[i] >= 0) append_csv_number(out, actor.s[i]);
      out += reversing_at(actor.reversing, i) ? ",1" : ",0";
      const PerceivedActor* perceived = perceived_by_actor[id];
      if (id == kEgo || perceived == nullptr) {
        out += ",,,,,,";
      } else {
        out += perceived->detected[i] != 0 ? ",1" : ",0";
        for (const std::vector<double>* column :
             {&perceived->x, &perceived->y, &perceived->heading, &perceived->speed}) {
          out += ',';
          if (perceived->detected[i] != 0) append_csv_number(out, (*column)[i]);
        }
        out += ',';
        if (perceived->detected[i] != 0) out += reversing_at(perceived->reversing, i) ? '1' : '0';
      }
      out += ',';
      if (!actor.signals.empty()) out += vehicle_signal_list(actor.signals[i]);
      out += '\n';
    }
  }
  return out;
}

std::string trace_json(const Trace& trace) {
  ordered_json actors = ordered_json::array();
  for (const TraceActor& actor : trace.actors) actors.push_back(actor_json(actor));
  ordered_json perceived = ordered_json::array();
  for (const PerceivedActor& entry : trace.perceived) perceived.push_back(perceived_json(entry));
  ordered_json lights = ordered_json::array();
  for (const TraceLight& light : trace.lights) lights.push_back(light_json(light));
  ordered_json collisions = ordered_json::array();
  for (const Collision& collision : trace.collisions)
    collisions.push_back(collision_json(collision));
  ordered_json events = ordered_json::array();
  for (const TraceEvent& event : trace.events) events.push_back(event_json(event));
  const ordered_json target = trace.ego_target
                                  ? ordered_json::array({trace.ego_target->x, trace.ego_target->y})
                                  : ordered_json(nullptr);
  const ordered_json sensing{{"vehicle_range", trace.sensing.vehicle_range},
                             {"pedestrian_range", trace.sensing.pedestrian_range},
                             {"limited", trace.sensing.limited}};
  const ordered_json document{{"format", trace_format_name},
                              {"version", trace_format_version},
                              {"map", trace.map_name},
                              {"seed", trace.seed},
                              {"dt", trace.dt},
                              {"end", end_reason_name(trace.end)},
                              {"ego_target", target},
                              {"sensing", sensing},
                              {"time", trace.time},
                              {"actors", std::move(actors)},
                              {"perceived", std::move(perceived)},
                              {"lights", std::move(lights)},
                              {"collisions", std::move(collisions)},
                              {"events", std::move(events)}};
  return document.dump() + "\n";
}

// The ego's target and its perception's reach: optional, so that traces written before they were
// recorded still read (no target, sensing not recorded).
void read_ego_target_and_sensing(const json& document, Trace& trace) {
  if (const auto target = document.find("ego_target");
      target != document.end() && !target->is_null()) {
    const json& point = require_array(*target, "ego_target");
    if (point.size() != 2) fail("ego_target", "expected [x, y]");
    trace.ego_target =
        MapPoint{read_number(point[0], "ego_target[0]"), read_number(point[1], "ego_target[1]")};
  }
  if (const auto sensing = document.find("sensing"); sensing != document.end()) {
    const json& object = require_object(*sensing, "sensing");
    trace.sensing.vehicle_range =
        read_number(member(object, "vehicle_range", "sensing"), "sensing.vehicle_range");
    trace.sensing.pedestrian_range =
        read_number(member(object, "pedestrian_range", "sensing"), "sensing.pedestrian_range");
    const json& limited = member(object, "limited", "sensing");
    if (!limited.is_boolean()) fail("sensing.limited", "expected true or false");
    trace.sensing.limited = limited.get<bool>();
  }
}

Trace trace_from_json(const std::string& text) {
  json document;
  try {
    document = json::parse(text);
  } catch (const json::parse_error& error) {
    throw std::runtime_error(std::string("trace JSON: not valid JSON: ") + error.what());
  }
  const std::string top;
  if (!document.is_object()) fail("top level", "expected an object");
  if (read_string(member(document, "format", top), "format") != trace_format_name)
    fail("format", "expected \"" + std::string(trace_format_name) + "\"");
  const std::int64_t version = read_integer(member(document, "version", top), "version");
  if (version != trace_format_version)
    fail("version", "version " + std::to_string(version) + " is not supported (expected " +
                        std::to_string(trace_format_version) + ")");

  Trace trace;
  trace.map_name = read_string(member(document, "map", top), "map");
  const json& seed = member(document, "seed", top);
  if (!seed.is_number_unsigned()) fail("seed", "expected a non-negative integer");
  trace.seed = seed.get<std::uint64_t>();
  trace.dt = read_number(member(document, "dt", top), "dt");
  trace.end = read_enum(member(document, "end", top), "end", all_end_reasons, end_reason_name);
  read_ego_target_and_sensing(document, trace);
  const json& time = require_array(member(document, "time", top), "time");
  for (std::size_t i = 0; i < time.size(); ++i)
    trace.time.push_back(read_number(time[i], element_path("time", i)));
  const std::size_t sample_count = trace.time.size();

  const json& actors = require_array(member(document, "actors", top), "actors");
  for (std::size_t i = 0; i < actors.size(); ++i)
    trace.actors.push_back(read_actor(actors[i], element_path("actors", i), sample_count));
  const json& perceived = require_array(member(document, "perceived", top), "perceived");
  for (std::size_t i = 0; i < perceived.size(); ++i)
    trace.perceived.push_back(read_perceived(perceived[i], element_path("perceived", i),
                                             sample_count, trace.actors.size()));
  const json& lights = require_array(member(document, "lights", top), "lights");
  for (std::size_t i = 0; i < lights.size(); ++i)
    trace.lights.push_back(read_light(lights[i], element_path("lights", i), sample_count));
  const json& collisions = require_array(member(document, "collisions", top), "collisions");
  for (std::size_t i = 0; i < collisions.size(); ++i)
    trace.collisions.push_back(
        read_collision(collisions[i], element_path("collisions", i), trace.actors.size()));
  const json& events = require_array(member(document, "events", top), "events");
  for (std::size_t i = 0; i < events.size(); ++i)
    trace.events.push_back(
        read_event(events[i], element_path("events", i), trace.collisions.size()));
  return trace;
}

}  // namespace scenfuzz
