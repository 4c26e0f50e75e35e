// Geographic (WGS84 latitude/longitude) to map coordinates and back, for maps whose header gives a
// UTM or transverse Mercator projection as a PROJ string. The transverse Mercator formulas are
// Krüger's series (accurate to well under a millimetre within a UTM zone).
#pragma once

#include <optional>
#include <string_view>

#include "physics/map/map_point.hpp"

namespace scenfuzz {

struct GeoPoint {
  double latitude = 0;   // degrees, north positive
  double longitude = 0;  // degrees, east positive
};

// A transverse Mercator projection on the WGS84 ellipsoid.
struct TransverseMercator {
  double central_meridian = 0;    // degrees
  double latitude_of_origin = 0;  // degrees
  double scale_factor = 0.9996;
  double false_easting = 500000;
  double false_northing = 0;
};

// Throws std::invalid_argument for a zone outside 1..60 (a programming error: parse_projection
// checks user input).
TransverseMercator utm_zone(int zone, bool south);
// Parses "+proj=utm +zone=10 [+south] ..." and "+proj=tmerc +lat_0=.. +lon_0=.. +k=.. +x_0=..
// +y_0=.."; nullopt for anything else (the caller reports it).
std::optional<TransverseMercator> parse_projection(std::string_view proj);

MapPoint project(const TransverseMercator& projection, GeoPoint point);
GeoPoint unproject(const TransverseMercator& projection, MapPoint point);

}  // namespace scenfuzz
