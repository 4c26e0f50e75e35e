#include "lang/value.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lang/demand.hpp"

namespace scenfuzz {

Value constant_value(double constant, SourceLocation location) {
  Value v;
  v.op = ValueOp::constant;
  v.constant = constant;
  v.location = location;
  return v;
}

Value parameter_value(int parameter, SourceLocation location) {
  Value v;
  v.op = ValueOp::parameter;
  v.parameter = parameter;
  v.location = location;
  return v;
}

namespace {

double apply(ValueOp op, double a, double b) {
  switch (op) {
    case ValueOp::add: return a + b;
    case ValueOp::subtract: return a - b;
    case ValueOp::multiply: return a * b;
    case ValueOp::divide: return a / b;
    case ValueOp::power: return std::pow(a, b);
    case ValueOp::negate: return -a;
    case ValueOp::constant:
    case ValueOp::parameter: break;
  }
  SCENFUZZ_DEMAND(false && "not an arithmetic operator");
  return 0.0;
}

}  // namespace

Value binary_value(ValueOp op, Value a, Value b, SourceLocation location) {
  if (a.op == ValueOp::constant && b.op == ValueOp::constant)
    return constant_value(apply(op, a.constant, b.constant), location);
  Value v;
  v.op = op;
  v.location = location;
  v.operands.push_back(std::move(a));
  v.operands.push_back(std::move(b));
  return v;
}

Value negated_value(Value a, SourceLocation location) {
  if (a.op == ValueOp::constant) return constant_value(-a.constant, location);
  Value v;
  v.op = ValueOp::negate;
  v.location = location;
  v.operands.push_back(std::move(a));
  return v;
}

bool is_constant(const Value& value) { return value.op == ValueOp::constant; }

double evaluate(const Value& value, std::span<const double> parameter_values) {
  switch (value.op) {
    case ValueOp::constant: return value.constant;
    case ValueOp::parameter:
      SCENFUZZ_DEMAND(value.parameter >= 0 &&
                      static_cast<std::size_t>(value.parameter) < parameter_values.size());
      return parameter_values[static_cast<std::size_t>(value.parameter)];
    case ValueOp::negate: return -evaluate(value.operands[0], parameter_values);
    default:
      return apply(value.op, evaluate(value.operands[0], parameter_values),
                   evaluate(value.operands[1], parameter_values));
  }
}

void collect_parameters(const Value& value, std::vector<int>& parameters) {
  if (value.op == ValueOp::parameter) parameters.push_back(value.parameter);
  for (const Value& operand : value.operands) collect_parameters(operand, parameters);
}

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

ValueRange hull(std::initializer_list<double> corners) {
  ValueRange range{kInfinity, -kInfinity};
  for (double corner : corners) {
    if (std::isnan(corner)) return {-kInfinity, kInfinity};
    range.lower = std::min(range.lower, corner);
    range.upper = std::max(range.upper, corner);
  }
  return range;
}

}  // namespace

ValueRange value_range(const Value& value, std::span<const Parameter> parameters) {
  switch (value.op) {
    case ValueOp::constant: return {value.constant, value.constant};
    case ValueOp::parameter: {
      const Parameter& parameter = parameters[static_cast<std::size_t>(value.parameter)];
      return {parameter.lower, parameter.upper};
    }
    case ValueOp::negate: {
      ValueRange a = value_range(value.operands[0], parameters);
      return {-a.upper, -a.lower};
    }
    default: break;
  }
  ValueRange a = value_range(value.operands[0], parameters);
  ValueRange b = value_range(value.operands[1], parameters);
  switch (value.op) {
    case ValueOp::add: return {a.lower + b.lower, a.upper + b.upper};
    case ValueOp::subtract: return {a.lower - b.upper, a.upper - b.lower};
    case ValueOp::multiply:
      return hull({a.lower * b.lower, a.lower * b.upper, a.upper * b.lower, a.upper * b.upper});
    case ValueOp::divide:
      if (b.lower <= 0.0 && b.upper >= 0.0) return {-kInfinity, kInfinity};
      return hull({a.lower / b.lower, a.lower / b.upper, a.upper / b.lower, a.upper / b.upper});
    case ValueOp::power:
      // x^y is monotonic in each argument for x >= 0, so its extremes lie on the corners.
      if (a.lower < 0.0) return {-kInfinity, kInfinity};
      return hull({std::pow(a.lower, b.lower), std::pow(a.lower, b.upper),
                   std::pow(a.upper, b.lower), std::pow(a.upper, b.upper)});
    default: return {-kInfinity, kInfinity};
  }
}

int precedence(ValueOp op) {
  switch (op) {
    case ValueOp::add:
    case ValueOp::subtract: return 1;
    case ValueOp::multiply:
    case ValueOp::divide: return 2;
    case ValueOp::power: return 3;
    case ValueOp::negate: return 4;
    case ValueOp::constant:
    case ValueOp::parameter: return 5;
  }
  return 5;
}

}  // namespace scenfuzz
