// The keys of a CH-Scenario entity module, as tables: a key's normalised spelling, how messages
// name it, where its value goes and what range it must lie in.
#include "lang/chs/fields.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "lang/edit_distance.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz::chs {

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

struct NumberKey {
  std::string_view key, what;
  Number& (*get)(File&);
  double low, high;  // inclusive
};

struct FlagKey {
  std::string_view key, what;
  Flag& (*get)(File&);
};

// Weather values are fractions of their worst; the air pressure is in atmospheres.
const std::array<NumberKey, 6> kWeather{{
    {"cloudiness", "the cloudiness", [](File& f) -> Number& { return f.weather.cloudiness; }, 0, 1},
    {"wetness", "the wetness", [](File& f) -> Number& { return f.weather.wetness; }, 0, 1},
    {"airpressure", "the air pressure", [](File& f) -> Number& { return f.weather.air_pressure; },
     0.1, 2},
    {"precipitation", "the precipitation",
     [](File& f) -> Number& { return f.weather.precipitation; }, 0, 1},
    {"windintensity", "the wind intensity",
     [](File& f) -> Number& { return f.weather.wind_intensity; }, 0, 1},
    {"visibility", "the visibility", [](File& f) -> Number& { return f.weather.visibility; }, 0, 1},
}};

const std::array<FlagKey, 12> kFlags{{
    {"rainstorm", "rainstorm", [](File& f) -> Flag& { return f.disaster.rainstorm; }},
    {"sandstorm", "sandstorm", [](File& f) -> Flag& { return f.disaster.sandstorm; }},
    {"typhoon", "typhoon", [](File& f) -> Flag& { return f.disaster.typhoon; }},
    {"tornado", "tornado", [](File& f) -> Flag& { return f.disaster.tornado; }},
    {"debrisflow", "debrisflow", [](File& f) -> Flag& { return f.disaster.debris_flow; }},
    {"landslide", "landslide", [](File& f) -> Flag& { return f.disaster.landslide; }},
    {"collapse", "collapse", [](File& f) -> Flag& { return f.disaster.collapse; }},
    {"rough", "rough", [](File& f) -> Flag& { return f.high_risk.rough; }},
    {"iceroad", "iceroad", [](File& f) -> Flag& { return f.high_risk.ice_road; }},
    {"steepdescentahead", "steepdescentahead",
     [](File& f) -> Flag& { return f.high_risk.steep_descent_ahead; }},
    {"muddy", "muddy", [](File& f) -> Flag& { return f.high_risk.muddy; }},
    {"wade", "wade", [](File& f) -> Flag& { return f.high_risk.wade; }},
}};

// Every key's spelling in the grammar, for suggestions.
const std::array<std::string_view, 36> kSpellings{
    "map",          "length",       "width",         "name",           "left boundary",
    "centre lines", "center lines", "road lines",    "right boundary", "cloudiness",
    "wetness",      "air_pressure", "precipitation", "wind_intensity", "visibility",
    "rainstorm",    "sandstorm",    "typhoon",       "tornado",        "debrisflow",
    "landslide",    "collapse",     "rough",         "iceroad",        "steepdescentahead",
    "muddy",        "wade",         "overview",      "timestamp",      "speed",
    "acceleration", "track",        "aim",           "centre line",    "center line",
    "position"};

bool in_range(const Number& number, double low, double high) {
  return number.value >= low && number.value <= high;
}

// Bounds as written in the docs: 100000, not 1e+05.
std::string bound(double value) {
  if (value == std::floor(value) && std::abs(value) < 1e15)
    return std::to_string(static_cast<long long>(value));
  return format_number(value);
}

std::string range_text(double low, double high) {
  if (high == kUnbounded) return "at least " + bound(low);
  return "from " + bound(low) + " to " + bound(high);
}

// A number for `what` within [low, high] into `into`, once.
void read_ranged(const Value& value, const std::string& what, double low, double high, Number& into,
                 Diagnostics& diagnostics) {
  std::optional<Number> number = read_number(value, diagnostics, what);
  if (!number) return;
  if (!in_range(*number, low, high)) {
    diagnostics.error(number->location, what + " must be " + range_text(low, high) + ", not " +
                                            format_number(number->value));
    return;
  }
  into = *number;
}

bool first_time(std::set<std::string>& seen, const std::string& key, SourceLocation key_at,
                std::string_view written, Diagnostics& diagnostics) {
  if (seen.insert(key).second) return true;
  diagnostics.error(key_at, "'" + std::string(written) + "' is given twice");
  return false;
}

}  // namespace

std::optional<Header> header_of(const std::string& key) {
  static const std::map<std::string, Header, std::less<>> kHeaders{
      {"roadnetwork", Header::road_network},
      {"weather", Header::weather},
      {"naturaldisaster", Header::disaster},
      {"neturaldisaster", Header::disaster},  // the BNF's spelling
      {"meteorologicaldisaster", Header::disaster},
      {"geologicaldisaster", Header::disaster},
      {"specialhighrisk", Header::high_risk},
      {"entity", Header::entities},
      {"entities", Header::entities},
      {"constraintlist", Header::constraints},
  };
  if (auto found = kHeaders.find(key); found != kHeaders.end()) return found->second;
  // StaticEntity and DynamicEntity, numbered or not.
  for (auto [word, header] :
       {std::pair{std::string_view("staticentity"), Header::static_entity},
        std::pair{std::string_view("dynamicentity"), Header::dynamic_entity}}) {
    if (!key.starts_with(word)) continue;
    std::string_view rest = std::string_view(key).substr(word.size());
    if (rest.find_first_not_of("0123456789") == std::string_view::npos) return header;
  }
  return std::nullopt;
}

bool read_global(const std::string& key, SourceLocation key_at, const Value& value, File& file,
                 std::set<std::string>& seen, Diagnostics& diagnostics) {
  const std::string_view written = value.line.text.substr(0, key_at.length);
  for (const NumberKey& entry : kWeather) {
    if (entry.key != key) continue;
    if (first_time(seen, key, key_at, written, diagnostics))
      read_ranged(value, std::string(entry.what), entry.low, entry.high, entry.get(file),
                  diagnostics);
    return true;
  }
  for (const FlagKey& entry : kFlags) {
    if (entry.key != key) continue;
    if (!first_time(seen, key, key_at, written, diagnostics)) return true;
    if (auto flag = read_flag(value, diagnostics, std::string(entry.what))) entry.get(file) = *flag;
    return true;
  }
  return false;
}

bool read_blank_map(const std::string& key, SourceLocation key_at, const Value& value,
                    MapSource& map, std::set<std::string>& seen, Diagnostics& diagnostics) {
  if (key != "length" && key != "width") return false;
  const std::string_view written = value.line.text.substr(0, key_at.length);
  if (!first_time(seen, key, key_at, written, diagnostics)) return true;
  // Up to 100 km: a map no vehicle crosses in a scenario's minutes is a mistake.
  read_ranged(value, "the map's " + key + " in metres", 1, 1e5,
              key == "length" ? map.length : map.width, diagnostics);
  return true;
}

std::vector<Point>* boundary_of(Road& road, const std::string& key) {
  if (key == "leftboundary") return &road.left_boundary;
  if (key == "rightboundary") return &road.right_boundary;
  if (key == "centrelines" || key == "centerlines" || key == "centreline" || key == "centerline" ||
      key == "roadlines")
    return &road.centre_lines;
  return nullptr;
}

namespace {

// One point, `(x, y)`: where an entity starts (scenfuzz's addition to the grammar).
std::optional<Point> read_position(const Value& value, Diagnostics& diagnostics) {
  std::vector<Point> points;
  if (!read_points(value.line, value.begin, points, diagnostics)) return std::nullopt;
  if (points.size() != 1) {
    diagnostics.error(points[1].location, "an entity's position is one point, (x, y)");
    return std::nullopt;
  }
  return points[0];
}

}  // namespace

void read_entity_key(PendingEntity& entity, const std::string& key, SourceLocation key_at,
                     std::string_view written, const Value& value, Diagnostics& diagnostics) {
  const bool is_static_key = key == "overview";
  const bool is_dynamic_key = key == "timestamp" || key == "speed" || key == "acceleration" ||
                              key == "track" || key == "aim";
  const bool is_shared_key = key == "name" || key == "position";
  if (!is_shared_key && !is_static_key && !is_dynamic_key) {
    diagnostics.error(key_at, unknown_key_message(written, key, "an entity"));
    return;
  }
  if (!first_time(entity.keys, key, key_at, written, diagnostics)) return;
  const EntityKind wanted = is_static_key    ? EntityKind::static_entity
                            : is_dynamic_key ? EntityKind::dynamic_entity
                                             : entity.kind;
  if (entity.kind == EntityKind::undecided) entity.kind = wanted;
  if (wanted != entity.kind) {
    diagnostics.error(key_at, "'" + std::string(written) + "' belongs to a " +
                                  (is_static_key ? "static" : "dynamic") +
                                  " entity, and this one is " +
                                  (is_static_key ? "dynamic" : "static"));
    return;
  }
  StaticEntity& s = entity.static_entity;
  DynamicEntity& d = entity.dynamic_entity;
  if (key == "name") {
    if (auto text = read_text(value, diagnostics, "the entity's name")) {
      s.name = d.name = *text;
      entity.named = true;
    }
  } else if (key == "position") {
    if (auto point = read_position(value, diagnostics)) s.position = d.position = *point;
  } else if (key == "overview") {
    if (auto text = read_text(value, diagnostics, "the entity's overview")) s.overview = *text;
  } else if (key == "timestamp") {
    if (auto text = read_text(value, diagnostics, "the entity's timestamp")) d.timestamp = *text;
  } else if (key == "track") {
    if (auto text = read_text(value, diagnostics, "the entity's track")) d.track = *text;
  } else if (key == "aim") {
    if (auto text = read_text(value, diagnostics, "the entity's aim")) d.aim = *text;
  } else if (key == "speed") {
    read_ranged(value, "the speed in km/h", 0, 300, d.speed, diagnostics);
  } else {
    read_ranged(value, "the acceleration in m/s^2", -15, 15, d.acceleration, diagnostics);
  }
}

std::string unknown_key_message(std::string_view written, const std::string& key,
                                const std::string& where) {
  std::string message = "unknown key '" + std::string(written) + "' in " + where;
  std::string_view best;
  std::size_t best_distance = std::max<std::size_t>(2, key.size() / 3) + 1;
  for (std::string_view spelling : kSpellings) {
    const std::size_t d = edit_distance_within(key, normalised(spelling), best_distance - 1);
    if (d < best_distance) {
      best_distance = d;
      best = spelling;
    }
  }
  if (!best.empty()) message += "; did you mean '" + std::string(best) + "'?";
  return message;
}

void check_whole_file(const File& file, Diagnostics& diagnostics) {
  const MapSource& map = file.map;
  if (map.kind == MapSource::Kind::none)
    diagnostics.error({1, 1, 0, 0},
                      "the file gives no map: add 'map: NAME' (a map scenfuzz "
                      "knows) or 'import from MAP' with a length and width");
  if (map.kind == MapSource::Kind::blank) {
    if (!map.length.location.known() || !map.width.location.known())
      diagnostics.error(map.location,
                        "'import from MAP' needs the map's 'length:' and "
                        "'width:' in metres");
    if (file.roads.empty())
      diagnostics.error(map.location,
                        "a blank map needs a road network: add 'RoadNetwork' "
                        "and a road");
  }
  if (map.kind == MapSource::Kind::named && !file.roads.empty())
    diagnostics.error(file.roads.front().location,
                      "a road network is laid on a blank map ('import from MAP') only; the map '" +
                          map.name.text + "' has its own roads");
  std::set<std::string> roads;
  for (const Road& road : file.roads) {
    if (!roads.insert(road.name.text).second)
      diagnostics.error(road.name.location, "road " + road.name.text + " is described twice");
    for (auto [points, what] : {std::pair{&road.left_boundary, "left boundary"},
                                std::pair{&road.centre_lines, "centre line"},
                                std::pair{&road.right_boundary, "right boundary"}})
      if (points->size() < 2)
        diagnostics.error(road.location, "road " + road.name.text +
                                             " needs at least two points "
                                             "in its " +
                                             what);
  }
  std::set<std::string> entities;
  auto check_name = [&](const Text& name) {
    if (!entities.insert(name.text).second)
      diagnostics.error(name.location, "entity '" + name.text + "' is described twice");
  };
  for (const StaticEntity& entity : file.static_entities) check_name(entity.name);
  std::set<std::string> constraints;
  for (const Constraint& constraint : file.constraints)
    if (!constraints.insert(constraint.name.text).second)
      diagnostics.error(constraint.name.location,
                        "constraint " + constraint.name.text + " is described twice");
  for (const DynamicEntity& entity : file.dynamic_entities) {
    check_name(entity.name);
    if (!entity.speed.location.known())
      diagnostics.error(entity.location,
                        "dynamic entity '" + entity.name.text + "' needs a 'speed:' in km/h");
  }
}

}  // namespace scenfuzz::chs
