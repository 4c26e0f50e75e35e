// Behaviour coverage: which of a fixed, documented set of features (docs/coverage.md) one
// simulated run covers: the ego's manoeuvres, the road features it traversed, its interactions
// with every other road user (class x WMG SDL sector x closing-speed band x minimum-distance band)
// and the weather and light it drove in. The corpus tools (`scenfuzz coverage`, `cmin`) compare
// seeds by these names; law specs add their own family (law_coverage.hpp).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "physics/ego/perception.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// Another road user whose body comes nearer the ego's than this is an interaction (the nearest
// road user a failure mode names lies within the same distance, failure_mode.hpp).
inline constexpr double kInteractionReach = 50;  // m
// Stopped with its front at most this far before a stop line (or this far past it): a stop there.
inline constexpr double kStopLineReach = 10;     // m
inline constexpr double kStopLineOvershoot = 2;  // m
// A light whose stop line lies at most this far ahead of the ego's front is met.
inline constexpr double kLightMetReach = 30;  // m

// The bands, named as the features name them (docs/coverage.md gives the edges and why).
// Closing speed: how fast the centres approach (m/s), the highest while in a sector.
std::string_view closing_speed_band(double closing_speed);
// The least gap between the bodies (m) while in a sector; `contact`: they collided there.
std::string_view distance_band(double gap, bool contact);
// A weather component's intensity in [0, 1]: "none", "light", "moderate", "heavy".
std::string_view weather_band(double intensity);
// Darkness in [0, 1] (perception.hpp's darkness_at): "day", "twilight", "night".
std::string_view light_band(double darkness);

// Every feature name the families above can give, sorted: the fixed set. Law sub-violations
// (law_coverage.hpp) depend on the specs and are not in it.
std::vector<std::string> behaviour_feature_names();

// The features `trace` covers on `map` under `conditions` (the run's weather and darkness),
// sorted and unique. One pass over the samples. An empty trace covers only the weather and light.
std::vector<std::string> behaviour_coverage(const Trace& trace, const RoadMap& map,
                                            const Conditions& conditions);

}  // namespace scenfuzz
