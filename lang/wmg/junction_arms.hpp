// Which arm of a built-in junction map each road a WMG junction connects becomes, read from the
// angles the file states between them (docs/wmg-semantics.md, "Junction arms"), whatever order
// the author wrote the roads and the angle pairs in: a T-junction's two roads at about 180
// degrees are its through road and the third its stem, a crossroads' opposite pairs are its two
// roads, a roundabout's arms follow round the ring a quarter turn apart.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/wmg/dynamic_syntax.hpp"
#include "lang/wmg/scenery_syntax.hpp"

namespace scenfuzz::wmg {

struct ArmLayout {
  std::vector<std::string> arms;  // per connected road, in the file's order: "west", "south", ...
  // The stated pair whose angle the generator's `angle` parameter is (the angle counter-clockwise
  // from the west arm to the south arm), or 180 minus it when `supplement`; none when no stated
  // pair varies it (it stays at its default, 90).
  std::optional<std::size_t> angle_pair;
  bool supplement = false;
};

// The arms of `map_name`'s generator ("crossroads", "t_junction", "roundabout") for the junction's
// connected roads. Of the assignments under which every stated angle range can hold, the one that
// puts the most actors of `initialisation` placed relative to another on another of the
// junction's roads on the side their sector names (FSR: to the right of the reference as it
// drives towards the junction, F: ahead across it, ...), the first in the generator's arm order
// (west, south, east, north for the first, second, ... road) among equals; nullopt after an error
// at the angles naming the conflict, or at a pair or lane connection naming a road the junction
// does not connect.
std::optional<ArmLayout> lay_out_arms(const Junction& junction, const std::string& map_name,
                                      const Initialisation& initialisation,
                                      Diagnostics& diagnostics);

}  // namespace scenfuzz::wmg
