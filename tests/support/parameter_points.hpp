// Parameter points that corpus tests try on every logical scenario: every parameter at its
// lowest, middle and highest value.
#pragma once

#include <vector>

#include "lang/scenario.hpp"

namespace scenfuzz::test {

// Three points: all lowest, all middle, all highest.
inline std::vector<std::vector<double>> corner_points(const ScenarioTemplate& scenario) {
  std::vector<std::vector<double>> points(3);
  for (const Parameter& parameter : scenario.parameters) {
    points[0].push_back(parameter.lower);
    points[1].push_back((parameter.lower + parameter.upper) / 2);
    points[2].push_back(parameter.upper);
  }
  return points;
}

}  // namespace scenfuzz::test
