// The ways through a junction a scenario says its map has (MapReference::links, from WMG's
// `Road lane connections`): each must be one the map builds, and an actor's turn should take one.
#pragma once

#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

// Reports an error at each link the map has no way for (no lanes of a junction lead from its
// lane into the junction to its lane out of it), naming where that lane does lead. False after
// an error.
bool check_lane_links(const RoadMap& map, const std::vector<LaneLink>& links,
                      Diagnostics& diagnostics);

// Warns when a turn phase (`wanted`) of an actor starting on `lane`, or its way straight on
// (LaneTurn::none: a vehicle without a turn phase takes the lanes ahead), leads out of the
// junction ahead by a lane its links from that lane do not name: the file contradicts itself,
// and the actor drives as its phases say.
void warn_of_turn_against_links(const RoadMap& map, const std::vector<LaneLink>& links,
                                LaneIndex lane, LaneTurn wanted, const std::string& what,
                                const SourceLocation& where, Diagnostics& diagnostics);

}  // namespace scenfuzz
