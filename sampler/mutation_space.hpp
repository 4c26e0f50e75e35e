// The parameter space scenfuzz derives around a concrete scenario, so that the concrete files users
// own (LawBreaker's scenest files have no ranges) are searched by mutation, as LawBreaker does:
// each actor's positions, lane offsets, headings and speeds (its start and its waypoints; the
// ego's start), the obstacles' positions and headings, the weather components and the time of day
// become parameters over a neighbourhood of the value written. Each parameter spans the number's
// text in the file, so a finding is the user's file with the mutated numbers (docs/search.md,
// "Concrete seeds").
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "lang/scenario.hpp"

namespace scenfuzz {

// position: where actors and obstacles start; waypoint: the points of an actor's path after its
// start (smaller, so that a path keeps its shape); lateral: lane offsets.
enum class MutationKind { position, waypoint, lateral, heading, speed, weather, time_of_day };
inline constexpr std::size_t kMutationKindCount = 7;

// The half-width of the neighbourhood of each kind, in its own unit: metres, metres, metres,
// degrees, m/s, intensity (0-1), hours. Zero leaves that kind's values as written.
struct MutationSizes {
  std::array<double, kMutationKindCount> half_width = {5, 2, 0.5, 15, 3, 0.3, 3};

  double& operator[](MutationKind kind) { return half_width[static_cast<std::size_t>(kind)]; }
  double operator[](MutationKind kind) const { return half_width[static_cast<std::size_t>(kind)]; }
};

// "position", "waypoint", "lateral", "heading", "speed", "weather", "time" (--mutate's names).
std::string_view mutation_kind_name(MutationKind kind);
std::optional<MutationKind> mutation_kind_named(std::string_view name);
// "m", "m", "m", "deg", "m/s", "", "h": the unit a --mutate size is written in.
std::string_view mutation_kind_unit(MutationKind kind);

// "position=5 lateral=0.5 ...": the sizes as --mutate options would set them.
std::string mutation_sizes_text(const MutationSizes& sizes);

// `--mutate KIND=SIZE` applied to `sizes`; an error message naming the problem, else nullopt.
std::optional<std::string> apply_mutation_option(const std::string& option, MutationSizes& sizes);

// Whether the search mutates `scenario`: it builds a scenario and has no parameter ranges (its
// only parameters, if any, choose whether probabilistic events fire: Parameter::event_outcome).
bool searched_by_mutation(const ScenarioTemplate& scenario);

// The concrete `scenario` with each mutable number replaced by a derived parameter over
// [value - half width, value + half width], clipped where the kind has bounds (speeds and lane
// arc lengths >= 0, intensities in [0, 1], times within the day). A number written once and used
// in several places (a variable) is one parameter. Numbers with no place in the file (defaults)
// stay as they are. The scenario's own parameters must all be event outcomes (demanded): they
// stay, first.
ScenarioTemplate derive_mutation_space(const ScenarioTemplate& scenario,
                                       const MutationSizes& sizes);

}  // namespace scenfuzz
