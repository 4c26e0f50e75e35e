// The scenery of a level-2 file (SCENERY_ELEMENTS): its junctions and roads, as written.
#pragma once

#include <optional>
#include <vector>

#include "lang/wmg/syntax_values.hpp"

namespace scenfuzz::wmg {

// `R1 -> R2` in "Angles between roads".
struct RoadPair {
  Identifier from;
  Identifier to;
  SourceLocation location;
  bool operator==(const RoadPair&) const = default;
};

// `R1.L1 -> R2.L1 + R3.L1` in "Road lane connections".
struct LaneConnection {
  LaneName from;
  std::vector<LaneName> to;
  SourceLocation location;
  bool operator==(const LaneConnection&) const = default;
};

// "Dimensions [Width: a, Depth: b]" or "Dimensions [Diameter: d]": either width and depth or
// diameter is set.
struct JunctionDimensions {
  std::optional<NumberRange> width;
  std::optional<NumberRange> depth;
  std::optional<NumberRange> diameter;
  SourceLocation location;
  bool operator==(const JunctionDimensions&) const = default;
};

// "Road signs [Stop, Warning] at [R1.L1, R2.L1]".
struct JunctionRoadSigns {
  std::vector<Label> signs;
  std::vector<LaneName> lanes;
  SourceLocation location;
  bool operator==(const JunctionRoadSigns&) const = default;
};

// `TL1 -> R1.L1` or `TL1 -> R1` (then lane is empty) in TRAFFIC_LIGHT_MAP.
struct TrafficLightPlacement {
  Identifier light;
  Identifier road;
  std::optional<Identifier> lane;
  SourceLocation location;
  bool operator==(const TrafficLightPlacement&) const = default;
};

// "Traffic light [With pedestrian crossing] as [TL1 -> R1.L1, ...]".
struct JunctionTrafficLights {
  Label type;
  std::vector<TrafficLightPlacement> lights;
  SourceLocation location;
  bool operator==(const JunctionTrafficLights&) const = default;
};

// JUNCTION_ELEMENT.
struct Junction {
  Identifier id;
  Label type;                // "Crossroads", "Mini roundabout", ... or a STRING
  Identifier named_as;       // the ID after "as"
  Label connection_control;  // "Traffic light", "Give way", "No" or a STRING
  WholeNumber connection_count;
  std::vector<Identifier> connected_roads;
  std::vector<RoadPair> angle_pairs;  // "Angles between roads": one angle per pair, in order
  std::vector<NumberRange> angles;
  std::vector<LaneConnection> lane_connections;
  JunctionDimensions dimensions;
  std::optional<JunctionRoadSigns> road_signs;
  std::optional<JunctionTrafficLights> traffic_lights;
  SourceLocation location;
  bool operator==(const Junction&) const = default;
};

// `S1: Curved` in a horizontal geometry map.
struct SegmentLabel {
  Identifier segment;
  Label value;
  SourceLocation location;
  bool operator==(const SegmentLabel&) const = default;
};

// `S1: 3.5 to 3.75` in a lane width map, or `S1: 500 to 900` / `S1: N/A` in a curvature radius
// map (range empty for N/A).
struct SegmentRange {
  Identifier segment;
  std::optional<NumberRange> range;
  SourceLocation location;
  bool operator==(const SegmentRange&) const = default;
};

// "Horizontal road geometry [Straight]" (whole_road) or "[S1: Straight, S2: Curved]" (segments).
struct HorizontalGeometry {
  std::optional<Label> whole_road;
  std::vector<SegmentLabel> segments;
  SourceLocation location;
  bool operator==(const HorizontalGeometry&) const = default;
};

// "with curvature radius of [S1: 500 to 900, ...]", or "[N/A]" (not_applicable, no segments).
struct CurvatureRadius {
  bool not_applicable = false;
  std::vector<SegmentRange> segments;
  SourceLocation location;
  bool operator==(const CurvatureRadius&) const = default;
};

// "Lane width [3.5 to 3.75]" (whole_road) or "[S1: 3.5, S2: 3.0 to 3.25]" (segments).
struct LaneWidth {
  std::optional<NumberRange> whole_road;
  std::vector<SegmentRange> segments;
  SourceLocation location;
  bool operator==(const LaneWidth&) const = default;
};

// "Special road structures [Bridge] as [B1] at [200] distance from START".
struct SpecialRoadStructure {
  Label type;
  Identifier id;
  NumberRange distance_from_start;
  SourceLocation location;
  bool operator==(const SpecialRoadStructure&) const = default;
};

// "Street lights: {spacing: 25 to 40, height: 8 to 12}".
struct StreetLights {
  NumberRange spacing;
  NumberRange height;
  SourceLocation location;
  bool operator==(const StreetLights&) const = default;
};

// One entry of "Fixed road structures [...]": a type (type.text is "Street lights" when
// street_lights is set), optionally "at [S1, S2]".
struct FixedRoadStructure {
  Label type;
  std::optional<StreetLights> street_lights;
  std::vector<Identifier> at;
  SourceLocation location;
  bool operator==(const FixedRoadStructure&) const = default;
};

// "Temporary road structures [Road works, ...] at [R1.L1]".
struct TemporaryRoadStructures {
  std::vector<Label> types;
  LaneName lane;
  SourceLocation location;
  bool operator==(const TemporaryRoadStructures&) const = default;
};

// "Road sign [Speed limit] as [S1] at [150] distance from START".
struct RoadSign {
  Label type;
  Identifier id;
  NumberRange distance_from_start;
  SourceLocation location;
  bool operator==(const RoadSign&) const = default;
};

// ROAD_ELEMENT, from `R1: START` to `END`.
struct Road {
  Identifier id;                             // R1
  std::optional<Identifier> start_junction;  // START: [J1]
  Label road_type;
  Identifier named_as;                     // the ROAD_ID after "as"
  Label zone;                              // "N/A" or a STRING
  std::optional<NumberRange> speed_limit;  // empty for N/A
  Label environment;                       // "Urban", "Rural" or a STRING
  WholeNumber lane_count;
  std::vector<LaneName> lanes;
  Label traffic_direction;
  Label lane_type;
  Label lane_markings;
  std::optional<Label> surface_type;
  std::optional<Label> surface_condition;
  std::optional<Label> surface_feature;
  HorizontalGeometry horizontal_geometry;
  std::optional<CurvatureRadius> curvature_radius;
  Label vertical_geometry;
  std::vector<Label> transverse_geometry;
  Label banking_angle;
  Label roadside_feature;
  std::optional<Label> edge_feature;
  std::vector<SpecialRoadStructure> special_structures;
  std::vector<FixedRoadStructure> fixed_structures;  // every "Fixed road structures" group
  std::vector<TemporaryRoadStructures> temporary_structures;
  std::vector<RoadSign> road_signs;
  NumberRange length;
  LaneWidth lane_width;
  std::optional<Identifier> end_junction;  // END: [J1]
  SourceLocation location;
  bool operator==(const Road&) const = default;
};

// SCENERY_ELEMENTS: "DO: 'description' [S1] as:", the junctions ("None" when empty), the roads.
struct Scenery {
  Text description;
  Identifier id;
  std::vector<Junction> junctions;
  std::vector<Road> roads;
  SourceLocation location;
  bool operator==(const Scenery&) const = default;
};

}  // namespace scenfuzz::wmg
