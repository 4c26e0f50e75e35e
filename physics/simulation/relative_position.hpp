// WMG SDL's relative initial positions (docs/wmg-semantics.md, "Actors"): an actor placed `s`
// metres along the lane from where its reference actor starts, in the lane written (else the
// reference's own lane, or its neighbour on the side a side sector names), `lateral` metres to
// the left, facing along the lane; a pedestrian on the side of its road its sector names.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "lang/diagnostic.hpp"
#include "lang/position.hpp"
#include "physics/map/lane_queries.hpp"

namespace scenfuzz {

// `reference` is the reference actor's initial pose. A `pedestrian` placed so that it would stand
// on the other side of the reference than a side sector (FSL, SL, RSL, FSR, SR, RSR) names stands
// on the named side of its road instead, beyond the outermost lane there by its lateral offset.
// Problems (no lane under the reference, an unknown lane, a place beyond either end of the lane)
// are errors at the position, naming `actor`.
std::optional<MapPose> place_relative(const RoadMap& map, const Position& position,
                                      std::span<const double> values, const MapPose& reference,
                                      bool pedestrian, const std::string& actor,
                                      Diagnostics& diagnostics);

}  // namespace scenfuzz
