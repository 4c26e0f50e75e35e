// Building the parameter space from a template, and the unit-cube encoding (see the header).
#include "sampler/parameter_space.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "lang/demand.hpp"

namespace scenfuzz {

ParameterSpace parameter_space(const ScenarioTemplate& scenario) {
  ParameterSpace space;
  space.dimensions.reserve(scenario.parameters.size());
  for (const Parameter& p : scenario.parameters)
    space.dimensions.push_back(
        {p.name, p.kind, p.lower, p.upper, p.unit, p.choices, p.location, p.origin});
  return space;
}

namespace {

// Number of cells of a discrete dimension.
std::size_t cell_count(const Dimension& d) {
  SCENFUZZ_DEMAND(!d.choices.empty() && "a discrete dimension needs at least one choice");
  return std::max<std::size_t>(d.choices.size(), 1);
}

double decode_one(const Dimension& d, double u) {
  SCENFUZZ_DEMAND(!std::isnan(u) && u >= 0.0 && u <= 1.0 && "unit-cube coordinate outside [0,1]");
  // Defined behaviour even when assertions are compiled out.
  u = std::isnan(u) ? 0.0 : std::clamp(u, 0.0, 1.0);
  if (d.kind == ParameterKind::discrete) {
    const std::size_t n = cell_count(d);
    const auto cell = static_cast<std::size_t>(std::floor(u * static_cast<double>(n)));
    return static_cast<double>(std::min(cell, n - 1));
  }
  SCENFUZZ_DEMAND(d.lower <= d.upper && "dimension with lower > upper");
  return std::lerp(d.lower, d.upper, u);  // exact at both ends, monotonic
}

double encode_one(const Dimension& d, double v) {
  SCENFUZZ_DEMAND(!std::isnan(v) && "NaN parameter value");
  if (d.kind == ParameterKind::discrete) {
    const std::size_t n = cell_count(d);
    SCENFUZZ_DEMAND(v >= 0.0 && v <= static_cast<double>(n - 1) && v == std::floor(v) &&
                    "discrete value is not a choice index");
    const double index = std::clamp(std::floor(v), 0.0, static_cast<double>(n - 1));
    return (index + 0.5) / static_cast<double>(n);
  }
  SCENFUZZ_DEMAND(v >= d.lower && v <= d.upper && "parameter value outside its dimension's bounds");
  const double width = d.upper - d.lower;
  if (!(width > 0.0)) return 0.5;
  return std::clamp((v - d.lower) / width, 0.0, 1.0);
}

}  // namespace

std::vector<double> decode(const ParameterSpace& space, std::span<const double> unit_point) {
  SCENFUZZ_DEMAND(unit_point.size() == space.dimensions.size() && "point has the wrong dimension");
  std::vector<double> values(space.dimensions.size());
  for (std::size_t i = 0; i < values.size() && i < unit_point.size(); ++i)
    values[i] = decode_one(space.dimensions[i], unit_point[i]);
  return values;
}

std::vector<double> encode(const ParameterSpace& space, std::span<const double> values) {
  SCENFUZZ_DEMAND(values.size() == space.dimensions.size() && "values have the wrong dimension");
  std::vector<double> point(space.dimensions.size());
  for (std::size_t i = 0; i < point.size() && i < values.size(); ++i)
    point[i] = encode_one(space.dimensions[i], values[i]);
  return point;
}

}  // namespace scenfuzz
