// Transverse Mercator on WGS84 by Krüger's series in the third flattening n, to order n^6, as in
// C. F. F. Karney, "Transverse Mercator with an accuracy of a few nanometers", J. Geodesy 85
// (2011), eqs. (7)-(11), (35)-(36). Truncating at n^6 leaves an error of a few nanometres within
// a UTM zone, so a forward and inverse round trip is exact to well under a micrometre.
#include "physics/map/utm.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace scenfuzz {
namespace {

constexpr double wgs84_semi_major_axis = 6378137.0;
constexpr double wgs84_flattening = 1 / 298.257223563;
constexpr double degree = std::numbers::pi / 180;

constexpr int series_order = 6;

struct KruegerSeries {
  double eccentricity = 0;
  double eccentricity_squared = 0;
  double rectifying_radius = 0;              // A: the meridian quadrant is A * pi / 2
  std::array<double, series_order> alpha{};  // conformal sphere -> rectifying (forward)
  std::array<double, series_order> beta{};   // rectifying -> conformal sphere (inverse)
};

KruegerSeries make_wgs84_series() {
  const double f = wgs84_flattening;
  const double n = f / (2 - f);
  const double n2 = n * n, n3 = n2 * n, n4 = n3 * n, n5 = n4 * n, n6 = n5 * n;
  KruegerSeries series;
  series.eccentricity_squared = f * (2 - f);
  series.eccentricity = std::sqrt(series.eccentricity_squared);
  series.rectifying_radius = wgs84_semi_major_axis / (1 + n) * (1 + n2 / 4 + n4 / 64 + n6 / 256);
  series.alpha = {
      n / 2 - 2 * n2 / 3 + 5 * n3 / 16 + 41 * n4 / 180 - 127 * n5 / 288 + 7891 * n6 / 37800,
      13 * n2 / 48 - 3 * n3 / 5 + 557 * n4 / 1440 + 281 * n5 / 630 - 1983433 * n6 / 1935360,
      61 * n3 / 240 - 103 * n4 / 140 + 15061 * n5 / 26880 + 167603 * n6 / 181440,
      49561 * n4 / 161280 - 179 * n5 / 168 + 6601661 * n6 / 7257600,
      34729 * n5 / 80640 - 3418889 * n6 / 1995840,
      212378941 * n6 / 319334400,
  };
  series.beta = {
      n / 2 - 2 * n2 / 3 + 37 * n3 / 96 - n4 / 360 - 81 * n5 / 512 + 96199 * n6 / 604800,
      n2 / 48 + n3 / 15 - 437 * n4 / 1440 + 46 * n5 / 105 - 1118711 * n6 / 3870720,
      17 * n3 / 480 - 37 * n4 / 840 - 209 * n5 / 4480 + 5569 * n6 / 90720,
      4397 * n4 / 161280 - 11 * n5 / 504 - 830251 * n6 / 7257600,
      4583 * n5 / 161280 - 108847 * n6 / 3991680,
      20648693 * n6 / 638668800,
  };
  return series;
}

const KruegerSeries& wgs84() {
  static const KruegerSeries series = make_wgs84_series();
  return series;
}

// The tangent of the conformal latitude from the tangent of the geodetic latitude. Tangents
// rather than angles keep full precision near the poles (Karney 2011, eqs. (7)-(9)).
double conformal_tangent(double tangent, double eccentricity) {
  const double sigma =
      std::sinh(eccentricity * std::atanh(eccentricity * tangent / std::hypot(1.0, tangent)));
  return tangent * std::hypot(1.0, sigma) - sigma * std::hypot(1.0, tangent);
}

// Inverts conformal_tangent by Newton's method (Karney 2011, eqs. (19)-(21)); it converges in
// two or three steps from this start.
double geodetic_tangent(double conformal, const KruegerSeries& series) {
  const double one_minus_e2 = 1 - series.eccentricity_squared;
  double tangent = conformal / one_minus_e2;
  const double tolerance = 1e-15 * std::max(1.0, std::abs(conformal));
  for (int iteration = 0; iteration < 10; ++iteration) {
    const double estimate = conformal_tangent(tangent, series.eccentricity);
    const double derivative = one_minus_e2 * std::hypot(1.0, estimate) * std::hypot(1.0, tangent) /
                              (1 + one_minus_e2 * tangent * tangent);
    const double step = (conformal - estimate) / derivative;
    tangent += step;
    if (std::abs(step) <= tolerance) break;
  }
  return tangent;
}

// Longitude relative to `reference`, in [-180, 180).
double longitude_difference(double longitude, double reference) {
  double difference = std::remainder(longitude - reference, 360.0);
  if (difference >= 180) difference -= 360;
  return difference;
}

struct Rectifying {
  double xi = 0;   // northing / A, from the equator
  double eta = 0;  // easting / A, from the central meridian
};

Rectifying to_rectifying(double latitude, double longitude_from_meridian) {
  const KruegerSeries& series = wgs84();
  const double lambda = longitude_from_meridian * degree;
  const double tau_prime = conformal_tangent(std::tan(latitude * degree), series.eccentricity);
  const double xi_prime = std::atan2(tau_prime, std::cos(lambda));
  const double eta_prime = std::asinh(std::sin(lambda) / std::hypot(tau_prime, std::cos(lambda)));
  Rectifying result{xi_prime, eta_prime};
  for (int j = 1; j <= series_order; ++j) {
    const double coefficient = series.alpha[static_cast<std::size_t>(j - 1)];
    result.xi += coefficient * std::sin(2 * j * xi_prime) * std::cosh(2 * j * eta_prime);
    result.eta += coefficient * std::cos(2 * j * xi_prime) * std::sinh(2 * j * eta_prime);
  }
  return result;
}

// Distance along the meridian from the equator to `latitude`, scaled by k0 as the map is.
double scaled_meridian_arc(const TransverseMercator& projection, double latitude) {
  return projection.scale_factor * wgs84().rectifying_radius * to_rectifying(latitude, 0).xi;
}

std::optional<double> parse_number(std::string_view text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<int> parse_integer(std::string_view text) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end) return std::nullopt;
  return value;
}

// A PROJ string's parameters: "+key=value" or "+flag" (the '+' is optional, as in PROJ).
struct ProjParameters {
  std::vector<std::pair<std::string_view, std::optional<std::string_view>>> entries;

  bool has(std::string_view key) const {
    for (const auto& [name, value] : entries)
      if (name == key) return true;
    return false;
  }
  // The first occurrence wins, as in PROJ. nullopt for an absent key or a flag without value.
  std::optional<std::string_view> value(std::string_view key) const {
    for (const auto& [name, entry_value] : entries)
      if (name == key) return entry_value;
    return std::nullopt;
  }
};

ProjParameters split_parameters(std::string_view proj) {
  ProjParameters parameters;
  std::size_t position = 0;
  while (position < proj.size()) {
    const std::size_t start = proj.find_first_not_of(" \t\r\n", position);
    if (start == std::string_view::npos) break;
    std::size_t end = proj.find_first_of(" \t\r\n", start);
    if (end == std::string_view::npos) end = proj.size();
    std::string_view token = proj.substr(start, end - start);
    if (token.starts_with('+')) token.remove_prefix(1);
    const std::size_t equals = token.find('=');
    if (equals == std::string_view::npos)
      parameters.entries.emplace_back(token, std::nullopt);
    else
      parameters.entries.emplace_back(token.substr(0, equals), token.substr(equals + 1));
    position = end;
  }
  return parameters;
}

// A parameter that, when given, must have this value; absent is fine.
bool absent_or(const ProjParameters& parameters, std::string_view key, std::string_view wanted) {
  if (!parameters.has(key)) return true;
  const auto value = parameters.value(key);
  return value && *value == wanted;
}

// A numeric tmerc parameter: its default when absent, nullopt when present but not a number.
std::optional<double> number_or(const ProjParameters& parameters, std::string_view key,
                                double fallback) {
  if (!parameters.has(key)) return fallback;
  const auto value = parameters.value(key);
  if (!value) return std::nullopt;
  return parse_number(*value);
}

std::optional<TransverseMercator> parse_tmerc(const ProjParameters& parameters) {
  const auto latitude_of_origin = number_or(parameters, "lat_0", 0);
  const auto central_meridian = number_or(parameters, "lon_0", 0);
  // PROJ spells the scale either way; +k_0 is the documented one, +k the older alias.
  const auto scale =
      parameters.has("k_0") ? number_or(parameters, "k_0", 1) : number_or(parameters, "k", 1);
  const auto false_easting = number_or(parameters, "x_0", 0);
  const auto false_northing = number_or(parameters, "y_0", 0);
  if (!latitude_of_origin || !central_meridian || !scale || !false_easting || !false_northing)
    return std::nullopt;
  if (std::abs(*latitude_of_origin) > 90 || std::abs(*central_meridian) > 180 || *scale <= 0)
    return std::nullopt;
  return TransverseMercator{.central_meridian = *central_meridian,
                            .latitude_of_origin = *latitude_of_origin,
                            .scale_factor = *scale,
                            .false_easting = *false_easting,
                            .false_northing = *false_northing};
}

std::optional<TransverseMercator> parse_utm(const ProjParameters& parameters) {
  const auto zone_text = parameters.value("zone");
  if (!zone_text) return std::nullopt;
  const auto zone = parse_integer(*zone_text);
  if (!zone || *zone < 1 || *zone > 60) return std::nullopt;
  return utm_zone(*zone, parameters.has("south"));
}

}  // namespace

TransverseMercator utm_zone(int zone, bool south) {
  if (zone < 1 || zone > 60)
    throw std::invalid_argument("UTM zone " + std::to_string(zone) + " is not in 1..60");
  return TransverseMercator{.central_meridian = zone * 6.0 - 183,
                            .latitude_of_origin = 0,
                            .scale_factor = 0.9996,
                            .false_easting = 500000,
                            .false_northing = south ? 10000000.0 : 0.0};
}

std::optional<TransverseMercator> parse_projection(std::string_view proj) {
  const ProjParameters parameters = split_parameters(proj);
  // Coordinates on another ellipsoid, datum or unit would be off by metres to kilometres, so
  // such maps are refused rather than misplaced. Absent means PROJ's default; map headers that
  // omit them mean WGS84.
  if (!absent_or(parameters, "ellps", "WGS84") || !absent_or(parameters, "datum", "WGS84") ||
      !absent_or(parameters, "units", "m"))
    return std::nullopt;
  if (parameters.has("a") || parameters.has("b") || parameters.has("rf") || parameters.has("f") ||
      parameters.has("es") || parameters.has("e") || parameters.has("R"))
    return std::nullopt;
  const auto name = parameters.value("proj");
  if (!name) return std::nullopt;
  if (*name == "utm") return parse_utm(parameters);
  // etmerc is PROJ's older name for the same Krüger-series projection.
  if (*name == "tmerc" || *name == "etmerc") return parse_tmerc(parameters);
  return std::nullopt;
}

MapPoint project(const TransverseMercator& projection, GeoPoint point) {
  const Rectifying rectifying = to_rectifying(
      point.latitude, longitude_difference(point.longitude, projection.central_meridian));
  const double scale = projection.scale_factor * wgs84().rectifying_radius;
  return MapPoint{
      projection.false_easting + scale * rectifying.eta,
      projection.false_northing + scale * rectifying.xi -
          scaled_meridian_arc(projection, projection.latitude_of_origin),
  };
}

GeoPoint unproject(const TransverseMercator& projection, MapPoint point) {
  const KruegerSeries& series = wgs84();
  const double scale = projection.scale_factor * series.rectifying_radius;
  const double xi = (point.y - projection.false_northing +
                     scaled_meridian_arc(projection, projection.latitude_of_origin)) /
                    scale;
  const double eta = (point.x - projection.false_easting) / scale;
  double xi_prime = xi;
  double eta_prime = eta;
  for (int j = 1; j <= series_order; ++j) {
    const double coefficient = series.beta[static_cast<std::size_t>(j - 1)];
    xi_prime -= coefficient * std::sin(2 * j * xi) * std::cosh(2 * j * eta);
    eta_prime -= coefficient * std::cos(2 * j * xi) * std::sinh(2 * j * eta);
  }
  const double sinh_eta = std::sinh(eta_prime);
  const double cos_xi = std::cos(xi_prime);
  const double conformal = std::sin(xi_prime) / std::hypot(sinh_eta, cos_xi);
  const double latitude = std::atan(geodetic_tangent(conformal, series)) / degree;
  const double longitude = std::atan2(sinh_eta, cos_xi) / degree;
  return GeoPoint{latitude, longitude_difference(longitude + projection.central_meridian, 0)};
}

}  // namespace scenfuzz
