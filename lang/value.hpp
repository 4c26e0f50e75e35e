// A numeric slot of the IR: a constant, a reference to a search parameter, or arithmetic over
// them (AVUnit allows `range(...)` inside arithmetic, e.g. `lead_speed + range(2, 6)`).
#pragma once

#include <span>
#include <vector>

#include "lang/parameter.hpp"
#include "lang/source_location.hpp"

namespace scenfuzz {

enum class ValueOp { constant, parameter, add, subtract, multiply, divide, power, negate };

struct Value {
  ValueOp op = ValueOp::constant;
  double constant = 0.0;        // op == constant
  int parameter = -1;           // op == parameter: index into ScenarioTemplate::parameters
  std::vector<Value> operands;  // one for negate, two for the binary operators
  SourceLocation location;

  bool operator==(const Value&) const = default;
};

Value constant_value(double constant, SourceLocation location = {});
Value parameter_value(int parameter, SourceLocation location = {});
// Builds `a op b`, folding it to a constant when both sides are constants.
Value binary_value(ValueOp op, Value a, Value b, SourceLocation location = {});
Value negated_value(Value a, SourceLocation location = {});

bool is_constant(const Value& value);
// The value with every parameter p replaced by parameter_values[p].
double evaluate(const Value& value, std::span<const double> parameter_values);
// Appends the parameters the value reads, in the order they appear.
void collect_parameters(const Value& value, std::vector<int>& parameters);

// The smallest and largest value a Value can take over its parameters' bounds (interval
// arithmetic; unbounded where it cannot tell, e.g. dividing by a range that contains zero).
struct ValueRange {
  double lower = 0.0;
  double upper = 0.0;
};
ValueRange value_range(const Value& value, std::span<const Parameter> parameters);

// Binding strength of an operator when printed: higher binds tighter.
int precedence(ValueOp op);

}  // namespace scenfuzz
