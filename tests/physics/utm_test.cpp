// UTM and transverse Mercator: published reference coordinates, round trips across whole zones,
// the sample maps' geo-references, and the PROJ strings the map headers use.
//
// Reference values:
//   - IOGP GIGS test dataset 2.1 (GIGS_conv_5101_TM_output_part2_JHS.txt, WGS 84 / UTM zone 31N,
//     EPSG:32631), published to the millimetre.
//   - GeographicLib 2.1 GeoConvert -u -p 6 (Karney's exact transverse Mercator), each also
//     reproduced to the micrometre by PROJ 9.1 cs2cs (+proj=utm / +proj=tmerc, +datum=WGS84).
#include "physics/map/utm.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace scenfuzz {
namespace {

constexpr double millimetre = 1e-3;
// About a millimetre of latitude, or of longitude at the equator.
constexpr double millimetre_in_degrees = 1e-3 / 111320;

struct ReferencePoint {
  std::string where;
  GeoPoint geo;
  int zone = 0;
  bool south = false;
  MapPoint utm;
};

// GeographicLib GeoConvert -u -p 6 -z ZONE; PROJ cs2cs gives the same to the micrometre.
std::vector<ReferencePoint> geographiclib_points() {
  return {
      {"san francisco map header (left/top)",
       {37.7882039998496, -122.39949797829956},
       10,
       false,
       {552873.985519, 4182486.019823}},
      {"san francisco civic centre",
       {37.7749, -122.4194},
       10,
       false,
       {551130.768481, 4180998.881499}},
      {"tainan, taiwan", {22.9, 120.2}, 51, false, {212760.524809, 2535182.447076}},
      {"shalun map header (left/top)",
       {22.999730099588586, 120.22702590254411},
       51,
       false,
       {215743.195958, 2546178.996226}},
      {"sydney (southern hemisphere)",
       {-33.8688, 151.2093},
       56,
       true,
       {334368.633648, 6250948.345385}},
      {"central meridian of zone 32", {45, 9}, 32, false, {500000, 4982950.400227}},
      {"equator, 2 degrees east of the meridian", {0, -121}, 10, false, {722595.439676, 0}},
      {"equator, 1.5 degrees west of the meridian", {0, -124.5}, 10, false, {333068.357011, 0}},
      {"84 north, UTM's northern limit", {84, -120}, 10, false, {534994.655061, 9329005.182447}},
      {"80 south, UTM's southern limit", {-80, -126.5}, 10, true, {432189.600930, 1116373.825882}},
  };
}

// GIGS 5101 part 2: WGS 84 / UTM zone 31N, transect A along 2W and transect B along 60N (which
// runs 5 degrees either side of the central meridian, beyond the zone). Northings south of the
// equator are negative: the CRS is the northern zone.
std::vector<ReferencePoint> gigs_points() {
  return {
      {"GIGS-5101-60", {80, -2}, 31, false, {403186.945, 8885748.708}},
      {"GIGS-5101-61", {60, -2}, 31, false, {221288.770, 6661953.041}},
      {"GIGS-5101-62", {40, -2}, 31, false, {73106.698, 4439746.917}},
      {"GIGS-5101-63", {20, -2}, 31, false, {-23538.687, 2219308.238}},
      {"GIGS-5101-64", {0, -2}, 31, false, {-57087.120, 0}},
      {"GIGS-5101-65", {-20, -2}, 31, false, {-23538.687, -2219308.238}},
      {"GIGS-5101-66", {-40, -2}, 31, false, {73106.698, -4439746.917}},
      {"GIGS-5101-67", {-60, -2}, 31, false, {221288.770, -6661953.041}},
      {"GIGS-5101-68", {-80, -2}, 31, false, {403186.945, -8885748.708}},
      {"GIGS-5101-69", {60, -5}, 31, false, {54506.435, 6678411.623}},
      {"GIGS-5101-70", {60, -4}, 31, false, {110043.299, 6672079.494}},
      {"GIGS-5101-71", {60, -3}, 31, false, {165640.332, 6666593.572}},
      {"GIGS-5101-73", {60, -1}, 31, false, {276979.926, 6658157.202}},
      {"GIGS-5101-74", {60, 0}, 31, false, {332705.179, 6655205.484}},
      {"GIGS-5101-75", {60, 1}, 31, false, {388455.958, 6653097.435}},
      {"GIGS-5101-76", {60, 2}, 31, false, {444223.733, 6651832.735}},
      {"GIGS-5101-77", {60, 3}, 31, false, {500000.000, 6651411.190}},
      {"GIGS-5101-78", {60, 4}, 31, false, {555776.267, 6651832.735}},
      {"GIGS-5101-79", {60, 5}, 31, false, {611544.042, 6653097.435}},
      {"GIGS-5101-80", {60, 6}, 31, false, {667294.821, 6655205.484}},
      {"GIGS-5101-81", {60, 7}, 31, false, {723020.074, 6658157.202}},
      {"GIGS-5101-82", {60, 8}, 31, false, {778711.230, 6661953.041}},
  };
}

void expect_matches(const TransverseMercator& projection, const ReferencePoint& reference,
                    double map_tolerance) {
  SCOPED_TRACE(reference.where);
  const MapPoint projected = project(projection, reference.geo);
  EXPECT_NEAR(projected.x, reference.utm.x, map_tolerance);
  EXPECT_NEAR(projected.y, reference.utm.y, map_tolerance);
  const GeoPoint unprojected = unproject(projection, reference.utm);
  EXPECT_NEAR(unprojected.latitude, reference.geo.latitude, millimetre_in_degrees);
  // A degree of longitude shrinks with the cosine of the latitude.
  EXPECT_NEAR(unprojected.longitude, reference.geo.longitude,
              millimetre_in_degrees / std::cos(reference.geo.latitude * std::numbers::pi / 180));
}

TEST(UtmZone, CentralMeridianAndFalseOrigin) {
  EXPECT_EQ(utm_zone(10, false).central_meridian, -123);
  EXPECT_EQ(utm_zone(51, false).central_meridian, 123);
  EXPECT_EQ(utm_zone(1, false).central_meridian, -177);
  EXPECT_EQ(utm_zone(60, false).central_meridian, 177);
  const TransverseMercator north = utm_zone(31, false);
  EXPECT_EQ(north.central_meridian, 3);
  EXPECT_EQ(north.scale_factor, 0.9996);
  EXPECT_EQ(north.false_easting, 500000);
  EXPECT_EQ(north.false_northing, 0);
  EXPECT_EQ(north.latitude_of_origin, 0);
  EXPECT_EQ(utm_zone(56, true).false_northing, 10000000);
}

TEST(UtmZone, RejectsZonesOutsideOneToSixty) {
  EXPECT_THROW(utm_zone(0, false), std::invalid_argument);
  EXPECT_THROW(utm_zone(61, true), std::invalid_argument);
}

TEST(UtmProjection, MatchesGeographicLibWithinAMillimetre) {
  for (const ReferencePoint& reference : geographiclib_points())
    expect_matches(utm_zone(reference.zone, reference.south), reference, millimetre);
}

// The implementation is good to nanometres; this pins it closer than the millimetre contract so
// that a wrong series coefficient cannot hide below the tolerance.
TEST(UtmProjection, MatchesGeographicLibWithinTenMicrometres) {
  for (const ReferencePoint& reference : geographiclib_points()) {
    SCOPED_TRACE(reference.where);
    const MapPoint projected = project(utm_zone(reference.zone, reference.south), reference.geo);
    EXPECT_NEAR(projected.x, reference.utm.x, 1e-5);
    EXPECT_NEAR(projected.y, reference.utm.y, 1e-5);
  }
}

TEST(UtmProjection, MatchesPublishedGigsValues) {
  // GIGS rounds to the millimetre, so half a millimetre of the tolerance is the rounding.
  for (const ReferencePoint& reference : gigs_points())
    expect_matches(utm_zone(reference.zone, reference.south), reference, millimetre);
}

TEST(UtmProjection, CentralMeridianHasFalseEastingAndEquatorHasFalseNorthing) {
  const TransverseMercator zone10 = utm_zone(10, false);
  for (double latitude = -80; latitude <= 84; latitude += 4)
    EXPECT_NEAR(project(zone10, {latitude, -123}).x, 500000, 1e-9) << latitude;
  for (double longitude = -126.5; longitude <= -119.5; longitude += 0.5)
    EXPECT_NEAR(project(zone10, {0, longitude}).y, 0, 1e-9) << longitude;
  for (double longitude = -126.5; longitude <= -119.5; longitude += 0.5)
    EXPECT_NEAR(project(utm_zone(10, true), {0, longitude}).y, 10000000, 1e-9) << longitude;
}

// The projection is symmetric about the central meridian and, apart from the false northing,
// about the equator.
TEST(UtmProjection, IsSymmetricAboutMeridianAndEquator) {
  const TransverseMercator zone = utm_zone(10, false);
  const MapPoint east = project(zone, {37.5, -121});
  const MapPoint west = project(zone, {37.5, -125});
  const MapPoint south = project(zone, {-37.5, -121});
  EXPECT_NEAR(east.x - 500000, 500000 - west.x, 1e-6);
  EXPECT_NEAR(east.y, west.y, 1e-6);
  EXPECT_NEAR(east.x, south.x, 1e-6);
  EXPECT_NEAR(east.y, -south.y, 1e-6);
}

TEST(UtmProjection, LongitudesWrapAroundTheAntimeridian) {
  const TransverseMercator zone60 = utm_zone(60, false);
  const MapPoint a = project(zone60, {-45, 179.5});
  const MapPoint b = project(zone60, {-45, -180.5});
  EXPECT_NEAR(a.x, b.x, 1e-6);
  EXPECT_NEAR(a.y, b.y, 1e-6);
  // Zone 1 seen from just across the antimeridian: longitudes come back in (-180, 180].
  const GeoPoint back = unproject(utm_zone(1, false), project(utm_zone(1, false), {10, 179}));
  EXPECT_NEAR(back.longitude, 179, 1e-9);
}

TEST(UtmProjection, RoundTripsAcrossTheZoneWithinAMicrometre) {
  struct Zone {
    int number;
    bool south;
  };
  for (const Zone zone : {Zone{10, false}, Zone{51, false}, Zone{56, true}, Zone{1, true}}) {
    const TransverseMercator projection = utm_zone(zone.number, zone.south);
    double worst = 0;
    for (int latitude_step = 0; latitude_step <= 164; ++latitude_step) {
      const double latitude = -80 + latitude_step;
      for (int longitude_step = -14; longitude_step <= 14; ++longitude_step) {
        const double longitude = projection.central_meridian + longitude_step * 0.25;
        const MapPoint there = project(projection, {latitude, longitude});
        const GeoPoint back = unproject(projection, there);
        const MapPoint again = project(projection, back);
        worst = std::max(worst, distance(there, again));
        EXPECT_NEAR(back.latitude, latitude, 1e-11) << latitude << " " << longitude;
        // Zone 1 reaches past -180, where longitudes come back wrapped.
        EXPECT_NEAR(std::remainder(back.longitude - longitude, 360.0), 0, 1e-11)
            << latitude << " " << longitude;
      }
    }
    EXPECT_LT(worst, 1e-6) << "zone " << zone.number;
  }
}

TEST(UtmProjection, MapToGeoToMapRoundTripsWithinAMicrometre) {
  const TransverseMercator zone = utm_zone(10, false);
  for (double easting = 170000; easting <= 830000; easting += 30000) {
    for (double northing = 0; northing <= 9300000; northing += 150000) {
      const MapPoint point{easting, northing};
      EXPECT_LT(distance(project(zone, unproject(zone, point)), point), 1e-6)
          << easting << " " << northing;
    }
  }
}

// The Apollo sample maps give their geo-reference both as a PROJ string and as a lon/lat corner;
// the corner must land among the map's lanes.
TEST(UtmProjection, SampleMapHeadersLandInsideTheirMaps) {
  const auto san_francisco =
      parse_projection("+proj=utm +zone=10 +ellps=WGS84 +datum=WGS84 +units=m +no_defs");
  ASSERT_TRUE(san_francisco);
  const MapPoint corner = project(*san_francisco, {37.7882039998496, -122.39949797829956});
  EXPECT_GT(corner.x, 552000);
  EXPECT_LT(corner.x, 555000);
  EXPECT_GT(corner.y, 4181000);
  EXPECT_LT(corner.y, 4184000);

  // shalun's lanes span x 215687..215810, y 2546081..2546272.
  const auto shalun =
      parse_projection("+proj=utm +zone=51 +ellps=WGS84 +datum=WGS84 +units=m +no_defs");
  ASSERT_TRUE(shalun);
  const MapPoint shalun_corner = project(*shalun, {22.999730099588586, 120.22702590254411});
  EXPECT_GT(shalun_corner.x, 215687);
  EXPECT_LT(shalun_corner.x, 215810);
  EXPECT_GT(shalun_corner.y, 2546081);
  EXPECT_LT(shalun_corner.y, 2546272);
}

void expect_same_projection(const TransverseMercator& actual, const TransverseMercator& expected) {
  EXPECT_EQ(actual.central_meridian, expected.central_meridian);
  EXPECT_EQ(actual.latitude_of_origin, expected.latitude_of_origin);
  EXPECT_EQ(actual.scale_factor, expected.scale_factor);
  EXPECT_EQ(actual.false_easting, expected.false_easting);
  EXPECT_EQ(actual.false_northing, expected.false_northing);
}

TEST(UtmParseProjection, ReadsTheSampleMapHeaders) {
  const auto zone10 =
      parse_projection("+proj=utm +zone=10 +ellps=WGS84 +datum=WGS84 +units=m +no_defs");
  ASSERT_TRUE(zone10);
  expect_same_projection(*zone10, utm_zone(10, false));
  const auto zone51 =
      parse_projection("+proj=utm +zone=51 +ellps=WGS84 +datum=WGS84 +units=m +no_defs");
  ASSERT_TRUE(zone51);
  expect_same_projection(*zone51, utm_zone(51, false));
}

TEST(UtmParseProjection, ReadsSouthAndLooseSpelling) {
  const auto south = parse_projection("+proj=utm +zone=56 +south +datum=WGS84");
  ASSERT_TRUE(south);
  expect_same_projection(*south, utm_zone(56, true));
  const auto bare = parse_projection("  proj=utm\tzone=3  ");
  ASSERT_TRUE(bare);
  expect_same_projection(*bare, utm_zone(3, false));
}

TEST(UtmParseProjection, ReadsTransverseMercator) {
  const auto with_k =
      parse_projection("+proj=tmerc +lat_0=37.7 +lon_0=-122.4 +k=1 +x_0=0 +y_0=0 +ellps=WGS84");
  ASSERT_TRUE(with_k);
  expect_same_projection(*with_k, {.central_meridian = -122.4,
                                   .latitude_of_origin = 37.7,
                                   .scale_factor = 1,
                                   .false_easting = 0,
                                   .false_northing = 0});
  const auto with_k0 = parse_projection(
      "+proj=tmerc +lat_0=-30 +lon_0=150 +k_0=0.9999 +x_0=200000 +y_0=-1000 +ellps=WGS84 "
      "+units=m");
  ASSERT_TRUE(with_k0);
  expect_same_projection(*with_k0, {.central_meridian = 150,
                                    .latitude_of_origin = -30,
                                    .scale_factor = 0.9999,
                                    .false_easting = 200000,
                                    .false_northing = -1000});
  // PROJ's defaults for what is left out.
  const auto defaults = parse_projection("+proj=tmerc +datum=WGS84");
  ASSERT_TRUE(defaults);
  expect_same_projection(*defaults, {.central_meridian = 0,
                                     .latitude_of_origin = 0,
                                     .scale_factor = 1,
                                     .false_easting = 0,
                                     .false_northing = 0});
}

// PROJ 9.1 cs2cs +proj=longlat +datum=WGS84 +to <the string>: the latitude of origin moves the
// northing by the meridian arc to it.
TEST(UtmParseProjection, TransverseMercatorMatchesProj) {
  struct Case {
    std::string proj;
    GeoPoint geo;
    MapPoint expected;
  };
  const std::vector<Case> cases = {
      {"+proj=tmerc +lat_0=37.7 +lon_0=-122.4 +k=1 +x_0=0 +y_0=0 +ellps=WGS84",
       {37.7882039998496, -122.39949797829956},
       {44.220313, 9789.906708}},
      {"+proj=tmerc +lat_0=-30 +lon_0=150 +k_0=0.9999 +x_0=200000 +y_0=-1000 +ellps=WGS84 +units=m",
       {-33.8688, 151.2093},
       {311884.374011, -430610.354716}},
      {"+proj=tmerc +lat_0=22.9 +lon_0=120.2 +k=1 +x_0=0 +y_0=0 +datum=WGS84 +units=m +no_defs",
       {22.999730099588586, 120.22702590254411},
       {2770.769643, 11044.696582}},
  };
  for (const Case& test_case : cases) {
    SCOPED_TRACE(test_case.proj);
    const auto projection = parse_projection(test_case.proj);
    ASSERT_TRUE(projection);
    const MapPoint projected = project(*projection, test_case.geo);
    EXPECT_NEAR(projected.x, test_case.expected.x, millimetre);
    EXPECT_NEAR(projected.y, test_case.expected.y, millimetre);
    const GeoPoint back = unproject(*projection, test_case.expected);
    EXPECT_NEAR(back.latitude, test_case.geo.latitude, millimetre_in_degrees);
    EXPECT_NEAR(back.longitude, test_case.geo.longitude, millimetre_in_degrees);
  }
}

TEST(UtmParseProjection, RejectsWhatItCannotProjectExactly) {
  for (const std::string bad : {
           "",
           "   ",
           "garbage",
           "+proj=utm",
           "+proj=utm +zone=0 +datum=WGS84",
           "+proj=utm +zone=61 +datum=WGS84",
           "+proj=utm +zone=-3",
           "+proj=utm +zone=10abc",
           "+proj=utm +zone=",
           "+proj=utm +zone",
           "+proj=utm +zone=10.5",
           "+proj=utm +zone=10 +ellps=GRS80",
           "+proj=utm +zone=10 +ellps=clrk66 +datum=NAD27",
           "+proj=utm +zone=10 +datum=NAD83",
           "+proj=utm +zone=10 +units=us-ft",
           "+proj=utm +zone=10 +a=6378137 +rf=298.257222101",
           "+proj=lcc +lat_1=33 +lat_2=45 +lat_0=39 +lon_0=-96 +datum=WGS84",
           "+proj=merc +datum=WGS84",
           "+proj=longlat +datum=WGS84",
           "+zone=10 +datum=WGS84",
           "+proj=tmerc +lat_0=abc +datum=WGS84",
           "+proj=tmerc +lat_0=95 +datum=WGS84",
           "+proj=tmerc +k=0 +datum=WGS84",
           "+proj=tmerc +k=-1 +datum=WGS84",
           "+proj=tmerc +x_0 +datum=WGS84",
           "+proj=tmerc +lon_0=1e999 +datum=WGS84",
       }) {
    EXPECT_FALSE(parse_projection(bad)) << '"' << bad << '"';
  }
}

}  // namespace
}  // namespace scenfuzz
