// The checks prepare_simulation makes on the values a scenario evaluates to at one point of the
// search space, against the bounds of simulation_limits.hpp: each reports a diagnostic at the
// value's place in the file, so that the search records the point as infeasible with the reason
// instead of failing deep inside the simulation.
#pragma once

#include <string>

#include "lang/diagnostic.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

// A speed `who` starts or moves at: finite, >= 0 and at most kMaxPedestrianSpeed or
// kMaxVehicleSpeed. False after reporting an error.
bool check_speed(double speed, bool pedestrian, const std::string& who, const SourceLocation& where,
                 Diagnostics& diagnostics);

// A position's coordinates: finite and within kMaxCoordinate of the map's origin. False after
// reporting an error.
bool check_position(MapPoint position, const SourceLocation& where, Diagnostics& diagnostics);

// A scenario's own duration: finite and at most kMaxScenarioDuration. False after reporting an
// error.
bool check_duration(double duration, const SourceLocation& where, Diagnostics& diagnostics);

// The road's friction (a share of dry asphalt's grip): finite and in (0, 1] (road_friction.hpp).
// False after reporting an error.
bool check_road_friction(double friction, const SourceLocation& where, Diagnostics& diagnostics);

// Warns when the ego starts farther than kFarFromLanes from every lane.
void warn_if_far_from_lanes(const RoadMap& map, MapPoint start, const SourceLocation& where,
                            Diagnostics& diagnostics);

// The ego's route to its target (from `start` to `target`) is shorter than kMinimumEgoRoute:
// reports why (both points off the map, where they are and how far from the lanes; or the target
// where the ego starts) as an error at `where`.
void report_empty_ego_route(const RoadMap& map, MapPoint start, MapPoint target,
                            const SourceLocation& where, Diagnostics& diagnostics);

// "850 m", "4210 km": a distance as a reader takes it in.
std::string distance_text(double metres);

}  // namespace scenfuzz
