// One dimension of a logical scenario's search space, as the user wrote it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lang/source_location.hpp"

namespace scenfuzz {

enum class ParameterKind {
  continuous,  // a real interval [lower, upper]
  angle,       // a real interval in `unit` (deg or rad)
  discrete,    // one of `choices`; its value is the index of the choice
};

struct Parameter {
  std::string name;  // where it sits, e.g. "npc1.init.speed", "ego.init.position.x"
  ParameterKind kind = ParameterKind::continuous;
  double lower = 0.0;                // continuous, angle; discrete: 0
  double upper = 0.0;                // continuous, angle; discrete: choices.size() - 1
  std::string unit;                  // "m", "m/s", "deg", "rad", "time of day", "" for fractions
  std::vector<std::string> choices;  // discrete only
  // The whole range construct in the source (`range(1, 10)`, or `range(a, b) & (c, d)` for a
  // coordinate offset, whose x and y parameters share it): what a concrete scenario replaces.
  SourceLocation location;
  // Set when scenfuzz derived the parameter around a concrete file's value (mutation,
  // sampler/mutation_space.hpp): that value, which `location` then spans.
  std::optional<double> origin;
  // Whether it chooses whether a probabilistic event fires (CH-Scenario's `probability:`): a
  // concrete file with such choices is still searched by mutation, the choices kept as they are.
  bool event_outcome = false;

  bool operator==(const Parameter&) const = default;
};

// "continuous", "angle" or "discrete", as `scenfuzz space` shows it.
std::string_view kind_name(ParameterKind kind);

}  // namespace scenfuzz
