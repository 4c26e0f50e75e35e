// The search space of a logical scenario: one dimension per template parameter, and the mapping
// between the unit cube [0,1]^d that search strategies work in and the parameters' own values.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lang/parameter.hpp"
#include "lang/scenario.hpp"
#include "lang/source_location.hpp"

namespace scenfuzz {

struct Dimension {
  std::string name;  // as in the template, e.g. "npc1.init.speed"
  ParameterKind kind = ParameterKind::continuous;
  double lower = 0.0;  // continuous, angle: the interval; discrete: 0
  double upper = 0.0;  // continuous, angle: the interval; discrete: choices.size() - 1
  std::string unit;
  std::vector<std::string> choices;  // discrete only
  SourceLocation location;           // the range construct in the user's file
  std::optional<double> origin;      // derived by mutation: the concrete value it varies

  bool operator==(const Dimension&) const = default;
};

struct ParameterSpace {
  std::vector<Dimension> dimensions;

  bool operator==(const ParameterSpace&) const = default;
};

// One dimension per template parameter, in the same order (dimension i is parameter i).
ParameterSpace parameter_space(const ScenarioTemplate& scenario);

// A point of the unit cube to parameter values. Continuous and angle dimensions map linearly
// onto [lower, upper] (0 -> lower, 1 -> upper exactly); a discrete dimension with n choices splits
// [0,1] into n equal cells and gives the index of the cell, min(floor(u * n), n - 1).
// unit_point must have one coordinate per dimension, each in [0,1] and not NaN (asserted).
std::vector<double> decode(const ParameterSpace& space, std::span<const double> unit_point);

// The inverse of decode: parameter values to a point of the unit cube. A discrete index goes to
// the middle of its cell, so decode(encode(v)) == v; a zero-width interval goes to 0.5.
// values must have one entry per dimension, inside its bounds (discrete: an integral index).
std::vector<double> encode(const ParameterSpace& space, std::span<const double> values);

}  // namespace scenfuzz
