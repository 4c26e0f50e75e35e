// How a concrete scenario's header names the value of a search dimension whose range sits inside
// an expression (`speed: 10 + range(-3, 3)`): the dimension's own value is the range's draw
// (-1.97), but the value the user reads is that of what they wrote (the speed, 8.03 m/s). The
// concrete printers (avunit::print_concrete) name such a dimension by the resulting value of the
// slot it is named after and where the draw came from: "lead.init.speed = 8.03 m/s, where
// range(-3, 3) drew -1.97 (base.avu:12:22)".
#pragma once

#include <optional>
#include <span>
#include <string>

#include "lang/scenario.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz {

// Where one dimension's value came from. `value` is the slot's (the expression's) value.
struct ParameterProvenance {
  double value = 0;
  double drawn = 0;
  std::string range_text;  // the range as written in the file, on one line
  SourceLocation location;
};

// The provenance of parameter `index` when its slot (the value at the path it is named after) is
// an expression around it; nullopt when the slot is the range itself (its value is its draw), or
// the parameter is discrete or a time of day (named by choice or clock time, never in arithmetic).
std::optional<ParameterProvenance> parameter_provenance(const SourceFile& file,
                                                        const ScenarioTemplate& scenario,
                                                        std::span<const double> values,
                                                        std::size_t index);

// "lead.init.speed = 8.03 m/s, where range(-3, 3) drew -1.97 (base.avu:12:22)".
std::string provenance_text(const SourceFile& file, const Parameter& parameter,
                            const ParameterProvenance& provenance);

// How parameter `index` at `values` is named to a user (a concrete scenario's header, `run`'s
// report): "ego.init.speed = 12 m/s", or provenance_text when its range sits in an expression.
std::string parameter_value_text(const SourceFile& file, const ScenarioTemplate& scenario,
                                 std::span<const double> values, std::size_t index);

}  // namespace scenfuzz
