// RSS parameters by name, so that the command line can override any of them.
#include "oracle/rss_parameters.hpp"

#include <charconv>
#include <cmath>

namespace scenfuzz {

const std::vector<RssParameterField>& rss_parameter_fields() {
  static const std::vector<RssParameterField> fields = {
      {"response_time_ego", &RssParameters::response_time_ego, "s"},
      {"response_time_other", &RssParameters::response_time_other, "s"},
      {"accel_max", &RssParameters::accel_max, "m/s^2"},
      {"brake_min", &RssParameters::brake_min, "m/s^2"},
      {"brake_max", &RssParameters::brake_max, "m/s^2"},
      {"brake_min_correct", &RssParameters::brake_min_correct, "m/s^2"},
      {"lateral_accel_max", &RssParameters::lateral_accel_max, "m/s^2"},
      {"lateral_brake_min", &RssParameters::lateral_brake_min, "m/s^2"},
      {"lateral_fluctuation_margin", &RssParameters::lateral_fluctuation_margin, "m"},
  };
  return fields;
}

namespace {

std::string known_names() {
  std::string names;
  for (const RssParameterField& field : rss_parameter_fields())
    names += (names.empty() ? "" : ", ") + std::string(field.name);
  return names;
}

std::optional<double> parse_number(std::string_view text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

// The problem with one assignment, or "" once it is applied.
std::string apply(RssParameters& parameters, std::string_view assignment) {
  const std::size_t equals = assignment.find('=');
  if (equals == std::string_view::npos)
    return "'" + std::string(assignment) + "' is not NAME=VALUE";
  const std::string_view name = assignment.substr(0, equals);
  for (const RssParameterField& field : rss_parameter_fields()) {
    if (field.name != name) continue;
    const std::optional<double> value = parse_number(assignment.substr(equals + 1));
    // Response times and accelerations divide or bound motion: zero would make braking
    // distances infinite or forbid every motion. Only the margin may be 0.
    const bool margin = field.field == &RssParameters::lateral_fluctuation_margin;
    if (!value || *value < 0 || (*value == 0 && !margin))
      return "'" + std::string(assignment) + "': the value must be a number " +
             (margin ? ">= 0" : "> 0");
    parameters.*field.field = *value;
    return "";
  }
  return "'" + std::string(name) + "' is not an RSS parameter (one of " + known_names() + ")";
}

}  // namespace

RssParametersOrError parse_rss_parameters(const std::vector<std::string>& assignments) {
  RssParameters parameters;
  for (const std::string& assignment : assignments)
    if (std::string problem = apply(parameters, assignment); !problem.empty())
      return {std::nullopt, std::move(problem)};
  return {parameters, ""};
}

}  // namespace scenfuzz
