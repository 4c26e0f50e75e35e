// Internal to outline_map.cpp: the lane geometry of one half of a road outline (the strip between
// the centre line and one boundary). The centre line is sampled, the half's width measured at
// each sample, and lane k of the half drawn as offsets of the centre line along the vertex
// normals. The rules are those of outline_map.hpp; this file only does the plane geometry.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "physics/map/map_description.hpp"
#include "physics/map/map_point.hpp"
#include "physics/map/polyline.hpp"

namespace scenfuzz::outline {

// A length rounded to the centimetre, for error messages: they name places, not bits.
std::string metres(double value);

// Samples are at most this far apart along the centre line (and at every vertex).
constexpr double kSampleSpacing = 5.0;
// A half narrower than this everywhere carries no lane.
constexpr double kMinimumHalfWidth = 1.0;
// The width a lane is aimed at: a half of mean width W has max(1, round(W / this)) lanes.
constexpr double kNominalLaneWidth = 3.5;

// A point of the centre line with its unit left normal: at a vertex the average of the adjacent
// segments' normals, between vertices the segment's own.
struct CentreSample {
  MapPoint point;
  MapPoint left_normal;
  double s = 0;  // arc length along the centre line
};

// The vertices of `centre_line` and points between them at most kSampleSpacing apart.
std::vector<CentreSample> sample_centre_line(const Polyline& centre_line);

// `samples` (of `centre_line`) with one more at each of `stations` (arc lengths inside the line)
// that no sample lies within a millimetre of, between vertices with its segment's normal. Junction
// cuts fall on samples this way, so the pieces of a cut lane meet exactly.
std::vector<CentreSample> with_stations(std::vector<CentreSample> samples,
                                        const Polyline& centre_line,
                                        std::span<const double> stations);

// The index of the sample within a millimetre of arc length `s`; one must be.
std::size_t sample_at(std::span<const CentreSample> samples, double s);

// Which way a point lies from the centre line, judged at the nearest centre-line point: the
// component of (point - nearest) along the normal there (positive: left). At a vertex the normal
// is the vertex normal, so a point beyond a bend's outer corner is judged fairly.
double side_of_centre_line(const Polyline& centre_line, MapPoint point);

// The distance from each sample to the nearest point of `boundary` (at least one point;
// repeated points are allowed).
std::vector<double> half_widths(std::span<const CentreSample> samples,
                                std::span<const MapPoint> boundary);

// How many lanes a half with these widths carries: 0 when every width is below
// kMinimumHalfWidth, else max(1, round(mean / kNominalLaneWidth)), the mean weighted by arc length.
int half_lane_count(std::span<const CentreSample> samples, std::span<const double> widths);

enum class HalfSide { right, left };

// The geometry of lane k (0 next to the centre line) of `lane_count` lanes in the half on `side`:
// centre line, left and right boundaries and width samples, in the lane's driving direction (the
// centre line's for the right half, against it for the left). Ids, neighbours and boundary types
// are the caller's.
LaneDescription half_lane(std::span<const CentreSample> samples, std::span<const double> widths,
                          HalfSide side, int lane_count, int k);

}  // namespace scenfuzz::outline
