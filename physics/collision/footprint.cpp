// Exact 2-D signed distances between footprints. Rectangles use the separating axis theorem:
// for two convex polygons the Minkowski difference only has edges parallel to theirs, so the
// smallest overlap over the four rectangle axes is exactly the penetration depth, and when an
// axis separates them the closest pair always includes a corner of one of them.
#include "physics/collision/footprint.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "lang/demand.hpp"

namespace scenfuzz {

namespace {

struct Axes {
  double cos = 1;  // the heading's unit vector (cos, sin); across it is (-sin, cos)
  double sin = 0;
};

Axes axes_of(const Footprint& body) { return {std::cos(body.heading), std::sin(body.heading)}; }

// `point` in the body's frame: x along its heading, y to its left.
MapPoint to_body_frame(const Footprint& body, const Axes& axes, MapPoint point) {
  const double dx = point.x - body.centre.x, dy = point.y - body.centre.y;
  return {dx * axes.cos + dy * axes.sin, -dx * axes.sin + dy * axes.cos};
}

// Signed distance from a point to a rectangle: negative inside, by the depth to the nearest edge.
double point_rectangle_distance(const Footprint& rectangle, const Axes& axes, MapPoint point) {
  const MapPoint local = to_body_frame(rectangle, axes, point);
  const double outside_x = std::abs(local.x) - rectangle.half_length;
  const double outside_y = std::abs(local.y) - rectangle.half_width;
  if (outside_x <= 0 && outside_y <= 0) return std::max(outside_x, outside_y);
  const double gap_x = std::max(outside_x, 0.0), gap_y = std::max(outside_y, 0.0);
  return std::sqrt(gap_x * gap_x + gap_y * gap_y);
}

// The squared distance from a point to a rectangle, 0 inside.
double squared_distance_outside(const Footprint& rectangle, const Axes& axes, MapPoint point) {
  const MapPoint local = to_body_frame(rectangle, axes, point);
  const double outside_x = std::max(std::abs(local.x) - rectangle.half_length, 0.0);
  const double outside_y = std::max(std::abs(local.y) - rectangle.half_width, 0.0);
  return outside_x * outside_x + outside_y * outside_y;
}

std::array<MapPoint, 4> corners(const Footprint& rectangle, const Axes& axes) {
  const double lx = rectangle.half_length * axes.cos, ly = rectangle.half_length * axes.sin;
  const double wx = -rectangle.half_width * axes.sin, wy = rectangle.half_width * axes.cos;
  const MapPoint c = rectangle.centre;
  return {{{c.x + lx + wx, c.y + ly + wy},
           {c.x - lx + wx, c.y - ly + wy},
           {c.x - lx - wx, c.y - ly - wy},
           {c.x + lx - wx, c.y + ly - wy}}};
}

// Half the extent of a rectangle projected on the unit direction (nx, ny).
double projected_radius(const Footprint& rectangle, const Axes& axes, double nx, double ny) {
  return rectangle.half_length * std::abs(axes.cos * nx + axes.sin * ny) +
         rectangle.half_width * std::abs(-axes.sin * nx + axes.cos * ny);
}

double rectangle_rectangle_distance(const Footprint& a, const Footprint& b) {
  const Axes axes_a = axes_of(a), axes_b = axes_of(b);
  const double dx = b.centre.x - a.centre.x, dy = b.centre.y - a.centre.y;
  const std::array<std::array<double, 2>, 4> normals = {{{axes_a.cos, axes_a.sin},
                                                         {-axes_a.sin, axes_a.cos},
                                                         {axes_b.cos, axes_b.sin},
                                                         {-axes_b.sin, axes_b.cos}}};
  double largest_gap = -std::numeric_limits<double>::infinity();
  for (const auto& [nx, ny] : normals) {
    const double gap = std::abs(dx * nx + dy * ny) - projected_radius(a, axes_a, nx, ny) -
                       projected_radius(b, axes_b, nx, ny);
    largest_gap = std::max(largest_gap, gap);
  }
  if (largest_gap <= 0) return largest_gap;
  double nearest_squared = std::numeric_limits<double>::infinity();
  for (MapPoint corner : corners(a, axes_a))
    nearest_squared = std::min(nearest_squared, squared_distance_outside(b, axes_b, corner));
  for (MapPoint corner : corners(b, axes_b))
    nearest_squared = std::min(nearest_squared, squared_distance_outside(a, axes_a, corner));
  return std::sqrt(nearest_squared);
}

}  // namespace

double signed_distance(const Footprint& a, const Footprint& b) {
  SCENFUZZ_DEMAND(a.half_length >= 0 && a.half_width >= 0 && b.half_length >= 0 &&
                  b.half_width >= 0);
  if (a.round && b.round) return distance(a.centre, b.centre) - a.half_length - b.half_length;
  if (a.round) return point_rectangle_distance(b, axes_of(b), a.centre) - a.half_length;
  if (b.round) return point_rectangle_distance(a, axes_of(a), b.centre) - b.half_length;
  return rectangle_rectangle_distance(a, b);
}

BodySide side_of(const Footprint& body, MapPoint point) {
  if (body.round) {
    const double bearing = angle_difference(
        std::atan2(point.y - body.centre.y, point.x - body.centre.x), body.heading);
    if (std::abs(bearing) <= std::numbers::pi / 4) return BodySide::front;
    if (std::abs(bearing) >= 3 * std::numbers::pi / 4) return BodySide::rear;
    return bearing > 0 ? BodySide::left : BodySide::right;
  }
  const MapPoint local = to_body_frame(body, axes_of(body), point);
  // |x| / half_length >= |y| / half_width, multiplied out so that a zero extent cannot divide.
  if (std::abs(local.x) * body.half_width >= std::abs(local.y) * body.half_length)
    return local.x >= 0 ? BodySide::front : BodySide::rear;
  return local.y > 0 ? BodySide::left : BodySide::right;
}

}  // namespace scenfuzz
