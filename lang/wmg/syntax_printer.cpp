// The level-2 printer's top level, its leaves, the header, the environment and the traffic model.
#include "lang/wmg/syntax_printer.hpp"

#include <charconv>
#include <cmath>

#include "lang/wmg/printer_parts.hpp"

namespace scenfuzz::wmg {

namespace detail {

// Fixed notation, never an exponent (the language has none), shortest text that reads back.
std::string number_text(double value) {
  char buffer[512];
  auto [end, error] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
  if (error != std::errc()) return "0";
  return std::string(buffer, end);
}

std::string label_text(const Label& label) {
  return label.is_string ? "'" + label.text + "'" : label.text;
}

std::string lane_text(const LaneName& lane) { return lane.road.name + "." + lane.lane.name; }

std::string bracketed(const std::string& text) { return "[" + text + "]"; }

std::string joined(const std::vector<std::string>& texts, const std::string& separator) {
  std::string result;
  for (std::size_t i = 0; i < texts.size(); ++i) result += (i > 0 ? separator : "") + texts[i];
  return result;
}

namespace {

std::string two_digits(long value) { return (value < 10 ? "0" : "") + std::to_string(value); }

std::string time_text(double seconds) {
  auto minutes = static_cast<long>(std::lround(seconds / 60));
  return two_digits(minutes / 60) + ":" + two_digits(minutes % 60);
}

std::string time_range_text(const NumberRange& range) {
  return range.is_range ? time_text(range.low) + " to " + time_text(range.high)
                        : time_text(range.low);
}

std::string print_header(const Header& header) {
  std::string out = "VERSION: " + std::to_string(header.version.major_part.value) + "." +
                    std::to_string(header.version.minor_part.value) + "\n";
  for (const Text& author : header.authors) out += "AUTHOR: '" + author.text + "'\n";
  if (header.extension) out += "EXTENSION: " + label_text(*header.extension) + "\n";
  if (header.npc_behaviour)
    out += "NPC BEHAVIOUR: " + phrase_of(vocabulary::npc_behaviour(), header.npc_behaviour->value) +
           "\n";
  return out;
}

std::string print_connectivity(const Connectivity& connectivity) {
  if (connectivity.none || !connectivity.link || !connectivity.technology ||
      !connectivity.positioning)
    return "None";
  return "Communication: " + label_text(*connectivity.link) + ": " +
         label_text(*connectivity.technology) +
         ", Positioning: " + label_text(*connectivity.positioning);
}

std::string print_environment(const Environment& environment) {
  std::string out = "ENVIRONMENT ELEMENTS:\nDO: " + bracketed(environment.id.name) + "\n";
  if (environment.wind) out += "  Wind " + bracketed(range_text(*environment.wind)) + "\n";
  out += "  Cloudiness " + bracketed(range_text(environment.cloudiness)) + "\n";
  if (environment.particulates)
    out += "  Particulates " + bracketed(label_text(*environment.particulates)) + "\n";
  out += "  Rainfall " +
         bracketed(label_text(environment.rainfall.type) + ": " +
                   range_text(environment.rainfall.intensity)) +
         "\n";
  if (environment.snowfall)
    out += "  Snowfall " +
           bracketed(label_text(environment.snowfall->type) +
                     " (visibility: " + range_text(environment.snowfall->visibility) + ")") +
           "\n";
  out += "  Time of the day " +
         bracketed(environment.time_of_day ? time_range_text(*environment.time_of_day) : "Any") +
         "\n";
  out += "  Illumination " + bracketed(label_text(environment.illumination)) + " with " +
         bracketed(label_text(environment.light_source)) + " as light source\n";
  if (environment.light_source_position)
    out += "    at " + bracketed(range_text(environment.light_source_position->elevation)) +
           " degree elevation AND " +
           bracketed(phrase_of(vocabulary::relative_location(),
                               environment.light_source_position->position.value)) +
           " position\n";
  if (environment.connectivity)
    out += "  Connectivity " + bracketed(print_connectivity(*environment.connectivity)) + "\n";
  return out;
}

std::string print_traffic(const TrafficModel& traffic) {
  std::string out = "TRAFFIC ELEMENTS:\nINITIAL:\n";
  for (std::size_t i = 0; i < traffic.centroids.size(); ++i) {
    const Centroid& centroid = traffic.centroids[i];
    out += std::string(i == 0 ? "  " : "  AND ") + "CENTROID " + bracketed(centroid.id.name) +
           " in " + bracketed(centroid.road.name) + " at " +
           bracketed(range_text(centroid.distance)) + " to " + bracketed(centroid.reference.name) +
           "\n";
  }
  out += "DO:\n";
  for (const TrafficFlow& flow : traffic.flows)
    out += "  TRAFFIC " + bracketed(flow.id.name) + ": " +
           bracketed(flow.source.name + ": " + lane_text(flow.source_lane) + ", " +
                     flow.destination.name + ": " + lane_text(flow.destination_lane)) +
           " at " + bracketed(range_text(flow.first) + ", " + range_text(flow.second)) + "\n";
  return out;
}

}  // namespace

}  // namespace detail

std::string range_text(const NumberRange& range) {
  return range.is_range ? detail::number_text(range.low) + " to " + detail::number_text(range.high)
                        : detail::number_text(range.low);
}

std::string print_level2(const Level2File& file) {
  std::string out = "# WMG SDL level 2, printed by scenfuzz\n";
  out += detail::print_header(file.header) + "\n";
  out += detail::print_scenery(file.scenery) + "\n";
  out += detail::print_dynamics(file.dynamics) + "\n";
  if (file.internal_elements)
    out += "INTERNAL ELEMENTS: '" + file.internal_elements->text + "'\n\n";
  out += detail::print_environment(file.environment);
  if (file.traffic) out += "\n" + detail::print_traffic(*file.traffic);
  return out;
}

}  // namespace scenfuzz::wmg
