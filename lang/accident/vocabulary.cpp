// The keyword and value tables of the accident formalism, as the grammar lists them.
#include "lang/accident/vocabulary.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <vector>

#include "lang/edit_distance.hpp"

namespace scenfuzz::accident {

namespace {

using Keywords = std::span<const std::string_view>;

constexpr std::string_view kFile[] = {"STATIC", "DYNAMIC", "ACCIDENT"};
constexpr std::string_view kStatic[] = {"ROAD", "TREE", "LIGHT", "CROSSING", "STOPSIGN"};
constexpr std::string_view kRoad[] = {"KIND"};
constexpr std::string_view kTree[] = {"ID", "COORD"};
constexpr std::string_view kLight[] = {"ID", "COLOR", "COORD"};
constexpr std::string_view kCoordOnly[] = {"COORD"};
constexpr std::string_view kDynamic[] = {"VEHICLE"};
constexpr std::string_view kVehicle[] = {"ID",        "KIND",    "INITDIRECTION",
                                         "STARTSIGN", "ENDSIGN", "CHAIN"};
constexpr std::string_view kChain[] = {"EVENT", "CRITICAL_EVENT"};
constexpr std::string_view kEvent[] = {"KIND"};
constexpr std::string_view kAccident[] = {"COLLISION"};
constexpr std::string_view kCollision[] = {"ACTOR", "VICTIM", "COORD"};

constexpr std::string_view kRepeatable[] = {"ROAD",     "TREE",           "LIGHT",
                                            "CROSSING", "STOPSIGN",       "VEHICLE",
                                            "EVENT",    "CRITICAL_EVENT", "COLLISION"};

constexpr Context kContexts[] = {
    Context::file,     Context::statics,   Context::road,     Context::tree,    Context::light,
    Context::crossing, Context::stop_sign, Context::dynamics, Context::vehicle, Context::chain,
    Context::event,    Context::accident,  Context::collision};

constexpr std::pair<std::string_view, RoadKind> kRoadKinds[] = {
    {"crossroad", RoadKind::crossroad},
    {"straightroad", RoadKind::straightroad},
    {"turn_left", RoadKind::turn_left},
    {"turn_right", RoadKind::turn_right}};
constexpr std::pair<std::string_view, Colour> kColours[] = {{"red", Colour::red},
                                                            {"orange", Colour::orange},
                                                            {"green", Colour::green},
                                                            {"inactive", Colour::inactive}};
constexpr std::pair<std::string_view, VehicleKind> kVehicleKinds[] = {
    {"car", VehicleKind::car}, {"truck", VehicleKind::truck}};
constexpr std::pair<std::string_view, Direction> kDirections[] = {{"north", Direction::north},
                                                                  {"south", Direction::south},
                                                                  {"east", Direction::east},
                                                                  {"west", Direction::west}};
constexpr std::pair<std::string_view, EventKind> kEventKinds[] = {
    {"driving_forward", EventKind::driving_forward},
    {"turn_left", EventKind::turn_left},
    {"turn_right", EventKind::turn_right},
    {"stop", EventKind::stop},
    {"overtake", EventKind::overtake},
    {"change_lane_left", EventKind::change_lane_left},
    {"change_lane_right", EventKind::change_lane_right}};
constexpr std::pair<std::string_view, Part> kParts[] = {{"front", Part::front},
                                                        {"rear", Part::rear},
                                                        {"leftside", Part::leftside},
                                                        {"rightside", Part::rightside},
                                                        {"unknown", Part::unknown}};

}  // namespace

std::span<const std::string_view> keywords_of(Context context) {
  switch (context) {
    case Context::file: return kFile;
    case Context::statics: return kStatic;
    case Context::road: return kRoad;
    case Context::tree: return kTree;
    case Context::light: return kLight;
    case Context::crossing:
    case Context::stop_sign: return kCoordOnly;
    case Context::dynamics: return kDynamic;
    case Context::vehicle: return kVehicle;
    case Context::chain: return kChain;
    case Context::event: return kEvent;
    case Context::accident: return kAccident;
    case Context::collision: return kCollision;
  }
  return kFile;
}

bool takes(Context context, std::string_view keyword) {
  const Keywords keywords = keywords_of(context);
  return std::find(keywords.begin(), keywords.end(), keyword) != keywords.end();
}

bool repeatable(std::string_view keyword) {
  return std::find(std::begin(kRepeatable), std::end(kRepeatable), keyword) !=
         std::end(kRepeatable);
}

bool is_keyword(std::string_view keyword) {
  return std::any_of(std::begin(kContexts), std::end(kContexts),
                     [&](Context context) { return takes(context, keyword); });
}

std::string context_name(Context context) {
  switch (context) {
    case Context::file: return "the file";
    case Context::statics: return "the STATIC part";
    case Context::road: return "a ROAD";
    case Context::tree: return "a TREE";
    case Context::light: return "a LIGHT";
    case Context::crossing: return "a CROSSING";
    case Context::stop_sign: return "a STOPSIGN";
    case Context::dynamics: return "the DYNAMIC part";
    case Context::vehicle: return "a VEHICLE";
    case Context::chain: return "a CHAIN";
    case Context::event: return "an EVENT";
    case Context::accident: return "the ACCIDENT part";
    case Context::collision: return "a COLLISION";
  }
  return "the file";
}

std::string keyword_list(Context context) {
  const Keywords keywords = keywords_of(context);
  std::string list;
  for (std::size_t i = 0; i < keywords.size(); ++i) {
    if (i > 0) list += i + 1 == keywords.size() ? " or " : ", ";
    list += keywords[i];
  }
  return list;
}

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::optional<std::string> nearest(std::string_view written,
                                   std::span<const std::string_view> candidates) {
  const std::string key = upper(written);
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(2, key.size() / 3) + 1;
  for (std::string_view candidate : candidates) {
    const std::size_t d = edit_distance_within(key, upper(candidate), best_distance - 1);
    if (d < best_distance) {
      best_distance = d;
      best = std::string(candidate);
    }
  }
  return best;
}

Choices<RoadKind> road_kinds() { return {"road kind", kRoadKinds}; }
Choices<Colour> colours() { return {"colour", kColours}; }
Choices<VehicleKind> vehicle_kinds() { return {"vehicle kind", kVehicleKinds}; }
Choices<Direction> directions() { return {"direction", kDirections}; }
Choices<EventKind> event_kinds() { return {"event kind", kEventKinds}; }
Choices<Part> parts() { return {"part", kParts}; }

}  // namespace scenfuzz::accident
