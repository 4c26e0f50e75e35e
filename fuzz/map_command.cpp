// `scenfuzz map NAME|FILE`: what a map holds (summary, JSON) and what it looks like (SVG), so a
// user can find lane ids before writing them into a scenario; `--list` shows the built-in maps.
// Given a scenario file, the map it builds at the centre of its space, and which of the map's
// roads each road of a WMG scenery became; its picture marks the actors where the run starts them
// and the WMG roads' names.
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "fuzz/atomic_file.hpp"
#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/scenario_marks.hpp"
#include "lang/number_format.hpp"
#include "physics/map/map_source.hpp"
#include "physics/map/map_svg.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz {

namespace {

constexpr std::size_t kWarningsShown = 5;

const char* turn_name(LaneTurn turn) {
  switch (turn) {
    case LaneTurn::none: return "none";
    case LaneTurn::left: return "left";
    case LaneTurn::right: return "right";
    case LaneTurn::u_turn: return "u_turn";
  }
  return "none";
}

std::string fixed(double value, int decimals) {
  if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0;  // never print "-0.00"
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

double total_lane_length(const RoadMap& map) {
  double total = 0;
  for (const Lane& lane : map.lanes()) total += lane.length();
  return total;
}

std::size_t junction_lane_count(const RoadMap& map) {
  std::size_t count = 0;
  for (const Lane& lane : map.lanes()) count += lane.junction ? 1 : 0;
  return count;
}

void print_summary(const RoadMap& map, std::ostream& out) {
  const MapBounds& bounds = map.bounds();
  out << "map         " << map.name() << "\n";
  out << "source      " << map.source() << "\n";
  if (!map.projection().empty()) out << "projection  " << map.projection() << "\n";
  out << "lanes       " << map.lanes().size() << " (" << fixed(total_lane_length(map) / 1000, 2)
      << " km of centre line, " << junction_lane_count(map) << " in junctions)\n";
  out << "junctions   " << map.junctions().size() << "\n";
  out << "signals     " << map.traffic_lights().size() << "\n";
  out << "stop signs  " << map.stop_sign_count() << "\n";
  out << "yield signs " << map.yield_sign_count() << "\n";
  out << "crosswalks  " << map.crosswalks().size() << "\n";
  out << "bounds      x " << fixed(bounds.min.x, 2) << " .. " << fixed(bounds.max.x, 2) << ", y "
      << fixed(bounds.min.y, 2) << " .. " << fixed(bounds.max.y, 2) << " ("
      << fixed(bounds.max.x - bounds.min.x, 1) << " m x " << fixed(bounds.max.y - bounds.min.y, 1)
      << " m)\n";
  if (!map.warnings().empty()) {
    out << "warnings    " << map.warnings().size()
        << " references to ids the map does not have were dropped:\n";
    for (std::size_t i = 0; i < map.warnings().size() && i < kWarningsShown; ++i)
      out << "  " << map.warnings()[i] << "\n";
    if (map.warnings().size() > kWarningsShown) out << "  ...\n";
  }
}

nlohmann::json lane_ids(const RoadMap& map, const std::vector<LaneIndex>& lanes) {
  nlohmann::json ids = nlohmann::json::array();
  for (LaneIndex lane : lanes) ids.push_back(map.lane(lane).id);
  return ids;
}

nlohmann::json point_json(MapPoint point) { return nlohmann::json::array({point.x, point.y}); }

nlohmann::json map_json(const RoadMap& map) {
  const MapBounds& bounds = map.bounds();
  nlohmann::json document;
  document["name"] = map.name();
  document["source"] = map.source();
  document["projection"] = map.projection();
  document["counts"] = {{"lanes", map.lanes().size()},
                        {"junctions", map.junctions().size()},
                        {"signals", map.traffic_lights().size()},
                        {"stop_signs", map.stop_sign_count()},
                        {"yield_signs", map.yield_sign_count()},
                        {"crosswalks", map.crosswalks().size()}};
  document["bounds"] = {{"min", point_json(bounds.min)}, {"max", point_json(bounds.max)}};
  nlohmann::json lanes = nlohmann::json::array();
  for (const Lane& lane : map.lanes()) {
    nlohmann::json entry;
    entry["id"] = lane.id;
    entry["length"] = lane.length();
    entry["speed_limit"] = lane.speed_limit;
    entry["turn"] = turn_name(lane.turn);
    entry["junction"] = lane.junction ? nlohmann::json(map.junctions()[*lane.junction].id)
                                      : nlohmann::json(nullptr);
    entry["start"] = point_json(lane.centre_line.points().front());
    entry["end"] = point_json(lane.centre_line.points().back());
    entry["successors"] = lane_ids(map, lane.successors);
    entry["predecessors"] = lane_ids(map, lane.predecessors);
    entry["left_forward_neighbours"] = lane_ids(map, lane.left_forward_neighbours);
    entry["right_forward_neighbours"] = lane_ids(map, lane.right_forward_neighbours);
    entry["left_reverse_neighbours"] = lane_ids(map, lane.left_reverse_neighbours);
    entry["right_reverse_neighbours"] = lane_ids(map, lane.right_reverse_neighbours);
    lanes.push_back(std::move(entry));
  }
  document["lanes"] = std::move(lanes);
  document["warnings"] = map.warnings();
  return document;
}

void print_builtin_maps(std::ostream& out) {
  for (const BuiltinMapInfo& info : builtin_maps()) {
    out << info.name << ": " << info.description << "\n";
    for (const MapParameterInfo& parameter : info.parameters) {
      out << "  " << parameter.name << " = " << format_number(parameter.default_value) << " ["
          << format_number(parameter.lower) << ", " << format_number(parameter.upper) << "]"
          << (parameter.unit.empty() ? "" : " " + parameter.unit) << "  " << parameter.description
          << "\n";
    }
  }
}

bool is_scenario_path(const std::string& name) {
  for (const char* extension : {".avu", ".scenest", ".sdl"})
    if (name.ends_with(extension)) return true;
  return false;
}

// The map a scenario file builds at the centre of its space, the notes it keeps on it (a WMG
// scenery's roads and the arms they became) and what its picture marks; nullopt after an error on
// `err`.
struct ScenarioDrawing {
  RoadMap map;
  std::vector<Attribute> notes;
  std::vector<SvgMark> marks;
};

std::optional<ScenarioDrawing> scenario_drawing(const MapCommandOptions& options,
                                                std::ostream& err) {
  const std::optional<ScenarioFile> input = read_scenario(options.name, "draw", err);
  if (!input) return std::nullopt;
  const ParameterSpace space = parameter_space(input->scenario);
  const std::vector<double> values =
      decode(space, std::vector<double>(space.dimensions.size(), 0.5));
  ScenarioDrawing drawing{
      load_scenario_map(input->scenario.map,
                        map_search_path({options.map_paths.begin(), options.map_paths.end()}),
                        values),
      input->scenario.map.attributes,
      {}};
  if (!options.svg_path.empty()) {
    // An actor that cannot be placed is told; the roads are drawn all the same.
    Diagnostics diagnostics;
    drawing.marks = scenario_marks(input->scenario, values, drawing.map, diagnostics);
    err << format_diagnostics(input->file, diagnostics);
  }
  return drawing;
}

void print_roads(const std::vector<Attribute>& notes, std::ostream& out) {
  for (const Attribute& note : notes)
    if (note.key.starts_with("road "))
      out << note.key << (note.key.size() < 12 ? std::string(12 - note.key.size(), ' ') : " ")
          << note.value << "\n";
}

}  // namespace

int run_map(const MapCommandOptions& options, std::ostream& out, std::ostream& err) {
  if (options.list) {
    print_builtin_maps(out);
    return kExitSuccess;
  }
  if (options.name.empty()) {
    err << "scenfuzz: error: map: give a map NAME or FILE (or --list)\n";
    return kExitUsage;
  }
  std::optional<RoadMap> map;
  std::vector<Attribute> notes;
  std::vector<SvgMark> marks;
  try {
    if (is_scenario_path(options.name)) {
      std::optional<ScenarioDrawing> drawing = scenario_drawing(options, err);
      if (!drawing) return kExitBadInput;
      map.emplace(std::move(drawing->map));
      notes = std::move(drawing->notes);
      marks = std::move(drawing->marks);
    } else {
      map.emplace(load_map(options.name,
                           map_search_path({options.map_paths.begin(), options.map_paths.end()})));
    }
  } catch (const MapError& error) {
    // Messages about a file already read `file:line:column: error: ...`.
    std::string_view message = error.what();
    err << (message.find(": error: ") != std::string_view::npos ? "scenfuzz: "
                                                                : "scenfuzz: error: ")
        << message << "\n";
    return kExitBadInput;
  }
  if (!options.svg_path.empty()) {
    SvgOptions svg;
    svg.labels = options.labels;
    std::string failure = write_file_atomically(options.svg_path, render_map_svg(*map, svg, marks));
    if (!failure.empty()) {
      err << "scenfuzz: error: " << failure << "\n";
      return kExitBadInput;
    }
  }
  if (options.json) {
    out << map_json(*map).dump(2) << "\n";
  } else {
    print_summary(*map, out);
    print_roads(notes, out);
  }
  return kExitSuccess;
}

}  // namespace scenfuzz
