// Map names to maps: built-in generators, Apollo files and the map search path; drawn roads.
#include "physics/map/map_source.hpp"

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <system_error>

#include "physics/map/apollo_map_reader.hpp"
#include "physics/map/outline_map.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

bool looks_like_path(std::string_view name) {
  return name.find('/') != std::string_view::npos || name.ends_with(".bin") ||
         name.ends_with(".txt") || name.starts_with(".");
}

// A folder holding an Apollo map: base_map.bin first (faster), then base_map.txt.
std::optional<fs::path> map_file_in(const fs::path& directory) {
  std::error_code error;
  for (const char* file : {"base_map.bin", "base_map.txt"}) {
    fs::path candidate = directory / file;
    if (fs::is_regular_file(candidate, error)) return candidate;
  }
  return std::nullopt;
}

double parse_parameter_value(std::string_view map, std::string_view key, std::string_view text) {
  if (text == "true" || text == "yes") return 1;
  if (text == "false" || text == "no") return 0;
  double value = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size())
    throw MapError("map '" + std::string(map) + "': parameter '" + std::string(key) +
                   "' needs a number, not '" + std::string(text) + "'");
  return value;
}

std::vector<MapPoint> evaluated_points(const std::vector<Point>& points,
                                       std::span<const double> parameter_values) {
  std::vector<MapPoint> result;
  for (const Point& point : points)
    result.push_back({evaluate(point.x, parameter_values), evaluate(point.y, parameter_values)});
  return result;
}

std::vector<RoadOutlineGeometry> evaluated_roads(const std::vector<RoadOutline>& roads,
                                                 std::span<const double> parameter_values) {
  std::vector<RoadOutlineGeometry> result;
  for (const RoadOutline& road : roads)
    result.push_back({road.name, evaluated_points(road.left_boundary, parameter_values),
                      evaluated_points(road.centre_line, parameter_values),
                      evaluated_points(road.right_boundary, parameter_values),
                      road.speed_limit ? evaluate(*road.speed_limit, parameter_values) : 0.0});
  return result;
}

// A signal's colour word (lang/scenario.hpp: red, yellow or green; none said: green).
SignalColour signal_colour(const std::string& word) {
  if (word == "red") return SignalColour::red;
  if (word == "yellow") return SignalColour::yellow;
  return SignalColour::green;
}

std::vector<OutlineSignal> outline_signals(const std::vector<JunctionSignal>& signals) {
  std::vector<OutlineSignal> result;
  for (const JunctionSignal& signal : signals)
    result.push_back(
        {signal.name, {signal.x, signal.y}, signal.road, signal_colour(signal.colour)});
  return result;
}

}  // namespace

MapSearchPath map_search_path(std::vector<fs::path> command_line) {
  MapSearchPath path{std::move(command_line)};
  if (const char* environment = std::getenv("SCENFUZZ_MAP_PATH")) {
    std::string_view rest = environment;
    while (!rest.empty()) {
      std::size_t colon = rest.find(':');
      std::string_view directory = rest.substr(0, colon);
      if (!directory.empty()) path.directories.emplace_back(directory);
      if (colon == std::string_view::npos) break;
      rest.remove_prefix(colon + 1);
    }
  }
  path.directories.emplace_back(SCENFUZZ_CORPORA_MAP_DIR);
  return path;
}

BuiltinMapRequest parse_builtin_map_request(std::string_view text) {
  BuiltinMapRequest request;
  std::size_t question = text.find('?');
  request.name = std::string(text.substr(0, question));
  if (question == std::string_view::npos) return request;
  // Every '&'-separated piece must be name=value: "a=1&" and "a=1&&b=2" have an empty one.
  std::string_view rest = text.substr(question + 1);
  for (;;) {
    std::size_t ampersand = rest.find('&');
    std::string_view pair = rest.substr(0, ampersand);
    std::size_t equals = pair.find('=');
    if (equals == std::string_view::npos || equals == 0)
      throw MapError("map '" + std::string(text) + "': expected name=value, found '" +
                     std::string(pair) + "'");
    std::string_view key = pair.substr(0, equals);
    request.parameters.push_back(
        {std::string(key), parse_parameter_value(request.name, key, pair.substr(equals + 1))});
    if (ampersand == std::string_view::npos) break;
    rest.remove_prefix(ampersand + 1);
  }
  return request;
}

std::string normalised_map_name(std::string_view name) {
  while (!name.empty() && name.front() == ' ') name.remove_prefix(1);
  while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
  std::string folder;
  for (char c : name) {
    if (c == ' ' || c == '-')
      folder += '_';
    else if (c >= 'A' && c <= 'Z')
      folder += static_cast<char>(c - 'A' + 'a');
    else
      folder += c;
  }
  return folder;
}

fs::path resolve_map_file(std::string_view name, const MapSearchPath& search_path) {
  std::error_code error;
  if (name.empty()) throw MapError("map name is empty");
  auto as_path = [&](const fs::path& path) {
    if (fs::is_directory(path, error)) {
      if (auto file = map_file_in(path)) return *file;
      throw MapError(path.string() + ": error: the folder has no base_map.bin or base_map.txt");
    }
    if (!fs::exists(path, error)) throw MapError(path.string() + ": error: no such file");
    return path;
  };
  if (looks_like_path(name)) return as_path(fs::path(name));
  for (const fs::path& directory : search_path.directories)
    if (auto file = map_file_in(directory / std::string(name))) return *file;
  // "San Francisco" names the san_francisco folder; the exact name came first.
  const std::string folder = normalised_map_name(name);
  if (folder != name)
    for (const fs::path& directory : search_path.directories)
      if (auto file = map_file_in(directory / folder)) return *file;
  // A bare name that is no map on the search path may still be a file here.
  if (fs::exists(fs::path(name), error)) return as_path(fs::path(name));
  std::string message = "map '" + std::string(name) + "' not found: it is not a built-in map (";
  for (std::size_t i = 0; i < builtin_maps().size(); ++i)
    message += (i ? ", " : "") + builtin_maps()[i].name;
  message += ") and no folder of the map search path has " + std::string(name) +
             "/base_map.bin or base_map.txt" +
             (folder != name ? " (nor " + folder + "/, its folder name)" : std::string()) +
             "; searched:";
  for (const fs::path& directory : search_path.directories)
    message += " '" + directory.string() + "'";
  message += " (add folders with --map-path DIR or SCENFUZZ_MAP_PATH)";
  throw MapError(message);
}

MapDescription describe_map(std::string_view name, const MapSearchPath& search_path,
                            const std::vector<MapParameterValue>& extra_parameters) {
  std::string_view base = name.substr(0, name.find('?'));
  if (is_builtin_map(base)) {
    BuiltinMapRequest request = parse_builtin_map_request(name);
    request.parameters.insert(request.parameters.end(), extra_parameters.begin(),
                              extra_parameters.end());
    return generate_builtin_map(request.name, request.parameters);
  }
  if (name.find('?') != std::string_view::npos) {
    std::string message = "map '" + std::string(name) +
                          "': only built-in maps take parameters, and '" + std::string(base) +
                          "' is not one (the built-in maps are ";
    for (std::size_t i = 0; i < builtin_maps().size(); ++i)
      message += (i ? ", " : "") + builtin_maps()[i].name;
    throw MapError(message + ")");
  }
  if (!extra_parameters.empty())
    throw MapError("map '" + std::string(name) + "': map parameters (" + extra_parameters[0].name +
                   ", ...) apply only to built-in maps");
  return read_apollo_map(resolve_map_file(name, search_path));
}

RoadMap load_map(std::string_view name, const MapSearchPath& search_path,
                 const std::vector<MapParameterValue>& extra_parameters) {
  return build_road_map(describe_map(name, search_path, extra_parameters));
}

RoadMap load_scenario_map(const MapReference& reference, const MapSearchPath& search_path,
                          std::span<const double> parameter_values) {
  // A scenario that draws its roads (CH-Scenario) names a blank map: the roads are the map.
  if (!reference.roads.empty())
    return build_road_map(describe_outline_map(reference.name,
                                               evaluated_roads(reference.roads, parameter_values),
                                               outline_signals(reference.signals)));
  std::vector<MapParameterValue> parameters;
  for (const NamedValue& parameter : reference.parameters)
    parameters.push_back({parameter.name, evaluate(parameter.value, parameter_values)});
  return load_map(reference.name, search_path, parameters);
}

}  // namespace scenfuzz
