// Where the traffic of a described road runs. An accident description names its road's kind
// (crossroad, straight road, left or right turn) and gives coordinates in its own frame: metres,
// x east, y north, the scene's centre at (0, 0), lanes 3.5 m wide, driving on the right
// (corpora/accident/README.md). scenfuzz simulates it on a built-in map (physics/map/builtin_*):
// this file is the one place that knows which map, with which parameters, where the
// description's frame lies on it, and along which line each direction's traffic arrives. The
// geometry repeats the built-in maps' contract (corpora/README.md); tests/lang/acc_translation_test
// checks it against the generated maps.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lang/accident/syntax.hpp"

namespace scenfuzz::accident {

struct PlanePoint {
  double x = 0, y = 0;
};

// One direction's way in: a vehicle that starts heading `direction` is `distance` metres before
// `entry`, in lane k `lane_offset(k)` metres to the right of the line through `entry` along
// `direction`.
struct Approach {
  PlanePoint entry;      // the description's frame
  PlanePoint direction;  // unit vector of travel
  PlanePoint right() const { return {direction.y, -direction.x}; }
};

struct SceneLayout {
  std::string map;                                         // a built-in map's name
  std::vector<std::pair<std::string, double>> parameters;  // the map's, by name
  int lanes = 1;                                           // each way
  double lane_width = 3.5;
  PlanePoint origin;  // where the description's (0, 0) lies on the map
  // The headings traffic can start with, each with its way in.
  std::vector<std::pair<Direction, Approach>> approaches;

  const Approach* approach(Direction heading) const;
  // Lane k's centre from the road's axis (k = 0 at the kerb), as the built-in maps lay lanes.
  double lane_offset(int k) const { return (lanes - k - 0.5) * lane_width; }
  PlanePoint on_map(PlanePoint p) const { return {p.x + origin.x, p.y + origin.y}; }
};

// The layout of a road of `kind` with `lanes` lanes each way.
SceneLayout scene_layout(RoadKind kind, int lanes);

// "north", "south", "east", "west".
std::string direction_name(Direction direction);

}  // namespace scenfuzz::accident
