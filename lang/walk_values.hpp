// Visits every numeric slot of a template with a readable path ("npc1.init.speed") and the unit
// its value is in. Parameter naming, instantiation and printing all walk the IR the same way.
#pragma once

#include <functional>
#include <string>

#include "lang/scenario.hpp"

namespace scenfuzz {

using ValueVisitor =
    std::function<void(Value& value, const std::string& path, const std::string& unit)>;
using ConstValueVisitor =
    std::function<void(const Value& value, const std::string& path, const std::string& unit)>;

// Order: map, ego, vehicles, pedestrians, obstacles, environment, traffic, specs, the rest.
void for_each_value(ScenarioTemplate& scenario, const ValueVisitor& visit);
void for_each_value(const ScenarioTemplate& scenario, const ConstValueVisitor& visit);

// The same walk over the pieces a front end holds before it has a whole template.
void for_each_value(State& state, const std::string& path, const ValueVisitor& visit);
void for_each_value(Position& position, const std::string& path, const ValueVisitor& visit);
void for_each_value(Heading& heading, const std::string& path, const ValueVisitor& visit);
void for_each_value(Formula& formula, const std::string& path, const ValueVisitor& visit);

}  // namespace scenfuzz
