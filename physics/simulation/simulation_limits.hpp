// The bounds on what a scenario may ask of the simulation, in one place: values beyond them
// (speeds no vehicle reaches, positions beyond any map, runs that would not fit in memory) are
// mistakes or search points at the edge of a careless range, and are reported as errors at their
// place in the file (prepare_simulation) instead of overflowing deep inside the simulation.
// docs/simulation.md ("Limits") lists them for users.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace scenfuzz {

// m/s: 720 km/h, above the top speed of any road vehicle (cars, trucks, motorcycles, bicycles).
inline constexpr double kMaxVehicleSpeed = 200;
// m/s: above any runner's sprint (about 12.4 m/s at best).
inline constexpr double kMaxPedestrianSpeed = 20;
// m from the map's origin in x and in y: UTM northings, the largest coordinates real maps use,
// stay below 1e7 m, so a position beyond this is no place on any map.
inline constexpr double kMaxCoordinate = 1e8;
// s: a scenario's own duration (12 hours); at the default dt of 0.05 s this is 864,001 samples.
inline constexpr double kMaxScenarioDuration = 43'200;
// Samples per actor a trace may hold (duration / dt + 1): a trace takes about 100 bytes per
// actor and sample, so this bounds a run at about 100 MB per actor.
inline constexpr std::size_t kMaxTraceSamples = 1'000'000;
// m: an ego that starts farther than this from every lane gets a warning: it would be
// simulated driving off the map.
inline constexpr double kFarFromLanes = 1'000;
// m: an ego route to a target shorter than this cannot be followed (the target is where the ego
// starts, or both lie off the map beyond the same lane end).
inline constexpr double kMinimumEgoRoute = 0.5;

// Why a run of `duration` s at `dt` s per step cannot be simulated (a non-positive or non-finite
// value, or more than kMaxTraceSamples samples), or nullopt when it can. For checking command-line
// options, and in simulate() itself.
std::optional<std::string> sample_count_problem(double duration, double dt);

}  // namespace scenfuzz
