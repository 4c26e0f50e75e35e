// The lane geometry of one half of a road outline (outline_half_road.hpp): sampling the centre
// line, measuring the half's width and offsetting the centre line into lanes.
#include "physics/map/outline_half_road.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>

#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "physics/map/plane_vectors.hpp"

namespace scenfuzz::outline {

namespace {

using namespace plane;

// Stations closer than this are one (a millimetre: map coordinates are given to the centimetre).
constexpr double kSameStation = 1e-3;

// The unit direction of segment i (Polyline drops repeated points, so it has a length).
MapPoint segment_direction(const std::vector<MapPoint>& points, std::size_t i) {
  MapPoint step = points[i + 1] - points[i];
  return (1 / norm(step)) * step;
}

// The average of the adjacent segments' unit left normals, made unit again. Where the line turns
// back on itself the average vanishes; the outgoing segment's normal stands in.
MapPoint vertex_normal(const std::vector<MapPoint>& points, std::size_t i) {
  const std::size_t last = points.size() - 1;
  if (i == 0) return left_normal(segment_direction(points, 0));
  if (i == last) return left_normal(segment_direction(points, last - 1));
  MapPoint sum = segment_direction(points, i - 1) + segment_direction(points, i);
  if (norm(sum) < 1e-9) return left_normal(segment_direction(points, i));
  return left_normal((1 / norm(sum)) * sum);
}

double distance_to_segment(MapPoint point, MapPoint a, MapPoint b) {
  MapPoint along = b - a;
  double length_squared = dot(along, along);
  double t =
      length_squared > 0 ? std::clamp(dot(point - a, along) / length_squared, 0.0, 1.0) : 0.0;
  return distance(point, a + t * along);
}

double distance_to_polyline(MapPoint point, std::span<const MapPoint> line) {
  if (line.size() == 1) return distance(point, line[0]);
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
    nearest = std::min(nearest, distance_to_segment(point, line[i], line[i + 1]));
  return nearest;
}

// Sample i moved `offset` metres along its normal (negative: to the right).
MapPoint offset_point(const CentreSample& sample, double offset) {
  return sample.point + offset * sample.left_normal;
}

// Width samples at the lane's own arc lengths, from its centre-line points.
std::vector<WidthSample> lane_widths(const std::vector<MapPoint>& centre,
                                     const std::vector<double>& half_widths) {
  std::vector<WidthSample> samples;
  double s = 0;
  for (std::size_t i = 0; i < centre.size(); ++i) {
    if (i > 0) s += distance(centre[i - 1], centre[i]);
    samples.push_back({s, half_widths[i]});
  }
  return samples;
}

}  // namespace

std::string metres(double value) { return format_number(std::round(value * 100) / 100); }

std::vector<CentreSample> sample_centre_line(const Polyline& centre_line) {
  const std::vector<MapPoint>& points = centre_line.points();
  const std::vector<double>& arc = centre_line.arc_lengths();
  std::vector<CentreSample> samples;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    samples.push_back({points[i], vertex_normal(points, i), arc[i]});
    const double length = arc[i + 1] - arc[i];
    const auto pieces = static_cast<std::size_t>(std::max(1.0, std::ceil(length / kSampleSpacing)));
    const MapPoint normal = left_normal(segment_direction(points, i));
    for (std::size_t j = 1; j < pieces; ++j) {
      double t = static_cast<double>(j) / static_cast<double>(pieces);
      samples.push_back({points[i] + t * (points[i + 1] - points[i]), normal, arc[i] + t * length});
    }
  }
  samples.push_back({points.back(), vertex_normal(points, points.size() - 1), arc.back()});
  return samples;
}

std::vector<CentreSample> with_stations(std::vector<CentreSample> samples,
                                        const Polyline& centre_line,
                                        std::span<const double> stations) {
  for (double s : stations) {
    const auto after = std::lower_bound(
        samples.begin(), samples.end(), s,
        [](const CentreSample& sample, double station) { return sample.s < station; });
    if (after != samples.end() && after->s - s < kSameStation) continue;
    if (after != samples.begin() && s - std::prev(after)->s < kSameStation) continue;
    const std::size_t segment = centre_line.segment_at(s);
    const MapPoint normal = left_normal(segment_direction(centre_line.points(), segment));
    samples.insert(after, {centre_line.point_at(s), normal, s});
  }
  return samples;
}

std::size_t sample_at(std::span<const CentreSample> samples, double s) {
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (std::abs(samples[i].s - s) < kSameStation) return i;
  demand_failed("a sample at the station", __FILE__, __LINE__);
}

double side_of_centre_line(const Polyline& centre_line, MapPoint point) {
  const PolylineProjection projection = centre_line.project(point);
  const std::vector<MapPoint>& points = centre_line.points();
  const std::vector<double>& arc = centre_line.arc_lengths();
  const std::size_t segment = projection.segment;
  MapPoint normal = left_normal(segment_direction(points, segment));
  // Nearest at a vertex: judge by the vertex normal, not by one of the segments meeting there.
  constexpr double kAtVertex = 1e-9;
  if (projection.s <= arc[segment] + kAtVertex) normal = vertex_normal(points, segment);
  if (projection.s >= arc[segment + 1] - kAtVertex) normal = vertex_normal(points, segment + 1);
  return dot(point - centre_line.point_at(projection.s), normal);
}

std::vector<double> half_widths(std::span<const CentreSample> samples,
                                std::span<const MapPoint> boundary) {
  SCENFUZZ_DEMAND(!boundary.empty());
  std::vector<double> widths;
  widths.reserve(samples.size());
  for (const CentreSample& sample : samples)
    widths.push_back(distance_to_polyline(sample.point, boundary));
  return widths;
}

int half_lane_count(std::span<const CentreSample> samples, std::span<const double> widths) {
  SCENFUZZ_DEMAND(samples.size() >= 2 && widths.size() == samples.size());
  if (*std::max_element(widths.begin(), widths.end()) < kMinimumHalfWidth) return 0;
  // The trapezoid rule: samples are not evenly spaced (every vertex is one).
  double area = 0;
  for (std::size_t i = 0; i + 1 < samples.size(); ++i)
    area += (samples[i + 1].s - samples[i].s) * (widths[i] + widths[i + 1]) / 2;
  const double mean = area / samples.back().s;
  return std::max(1, static_cast<int>(std::lround(mean / kNominalLaneWidth)));
}

LaneDescription half_lane(std::span<const CentreSample> samples, std::span<const double> widths,
                          HalfSide side, int lane_count, int k) {
  SCENFUZZ_DEMAND(widths.size() == samples.size() && lane_count > 0 && k >= 0 && k < lane_count);
  // Offsets grow away from the centre line: to the right for the right half.
  const double outwards = side == HalfSide::right ? -1 : 1;
  const double n = lane_count;
  LaneDescription lane;
  std::vector<double> half_lane_widths;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double lane_width = widths[i] / n;
    lane.centre_line.push_back(offset_point(samples[i], outwards * (k + 0.5) * lane_width));
    // Both directions have the centre line on their left: the inner edge is the lane's left.
    lane.left_boundary.push_back(offset_point(samples[i], outwards * k * lane_width));
    lane.right_boundary.push_back(offset_point(samples[i], outwards * (k + 1) * lane_width));
    half_lane_widths.push_back(lane_width / 2);
  }
  if (side == HalfSide::left) {
    std::reverse(lane.centre_line.begin(), lane.centre_line.end());
    std::reverse(lane.left_boundary.begin(), lane.left_boundary.end());
    std::reverse(lane.right_boundary.begin(), lane.right_boundary.end());
    std::reverse(half_lane_widths.begin(), half_lane_widths.end());
  }
  lane.left_width = lane_widths(lane.centre_line, half_lane_widths);
  lane.right_width = lane.left_width;
  return lane;
}

}  // namespace scenfuzz::outline
