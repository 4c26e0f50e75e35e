// The FCL facade: the only source file that includes FCL. The broadphase is the project's own
// sweep-and-prune over the bodies' footprint bounds (body_sweep.hpp); static-static pairs and
// pairs the caller no longer needs are dropped before the narrowphase. Every remaining candidate
// goes through FCL's narrowphase; the contact point and sides come from the footprints.
#include "physics/collision/collision_world.hpp"

#include <fcl/fcl.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>

#include "lang/demand.hpp"
#include "physics/collision/body_sweep.hpp"
#include "physics/collision/turned_reach.hpp"

namespace scenfuzz {

namespace {

// A disc's footprint is clipped as a regular polygon drawn around it, so that two overlapping
// footprints always give a non-empty intersection. It only places the contact point.
constexpr int kDiscPolygonSides = 16;

bool is_round(BodyShape shape) { return shape != BodyShape::box; }

double positive_dimension(double value, const char* shape, const char* what) {
  if (!std::isfinite(value) || value <= 0)
    throw std::invalid_argument(std::string("a ") + shape + "'s " + what +
                                " must be a positive number, not " + std::to_string(value));
  return value;
}

const char* shape_name(BodyShape shape) {
  switch (shape) {
    case BodyShape::box: return "box";
    case BodyShape::cylinder: return "cylinder";
    case BodyShape::sphere: return "sphere";
    case BodyShape::cone: return "cone";
  }
  return "body";
}

void check_geometry(const BodyGeometry& geometry) {
  const char* shape = shape_name(geometry.shape);
  positive_dimension(geometry.length, shape, "length");
  positive_dimension(geometry.width, shape, "width");
  positive_dimension(geometry.height, shape, "height");
  if (is_round(geometry.shape) && geometry.length != geometry.width)
    throw std::invalid_argument(std::string("a ") + shape +
                                "'s length and width are both its diameter and must be equal (" +
                                std::to_string(geometry.length) + " and " +
                                std::to_string(geometry.width) + ")");
}

void check_pose(const MapPose& pose) {
  if (!std::isfinite(pose.position.x) || !std::isfinite(pose.position.y) ||
      !std::isfinite(pose.heading))
    throw std::invalid_argument("a body's pose must be finite");
}

std::shared_ptr<fcl::CollisionGeometryd> make_shape(const BodyGeometry& geometry) {
  const double radius = geometry.length / 2;
  switch (geometry.shape) {
    case BodyShape::box:
      return std::make_shared<fcl::Boxd>(geometry.length, geometry.width, geometry.height);
    case BodyShape::cylinder: return std::make_shared<fcl::Cylinderd>(radius, geometry.height);
    case BodyShape::sphere: return std::make_shared<fcl::Sphered>(radius);
    case BodyShape::cone: return std::make_shared<fcl::Coned>(radius, geometry.height);
  }
  throw std::invalid_argument("unknown body shape");
}

// FCL shapes are centred on their origin; bodies stand on the ground, so lift them by half their
// height (a sphere by its radius). Cylinders and cones are z-aligned, the cone's base down.
fcl::Transform3d transform_of(const BodyGeometry& geometry, const MapPose& pose) {
  const double lift =
      geometry.shape == BodyShape::sphere ? geometry.length / 2 : geometry.height / 2;
  fcl::Transform3d transform = fcl::Transform3d::Identity();
  transform.translation() = fcl::Vector3d(pose.position.x, pose.position.y, lift);
  transform.linear() = Eigen::AngleAxisd(pose.heading, fcl::Vector3d::UnitZ()).toRotationMatrix();
  return transform;
}

Footprint footprint_of(const BodyGeometry& geometry, const MapPose& pose) {
  return {pose.position, pose.heading, geometry.length / 2, geometry.width / 2,
          is_round(geometry.shape)};
}

struct Bounds {
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
};

// How far a footprint reaches from its centre along x and along y.
struct Reach {
  double x = 0, y = 0;
};

Reach reach_of(const Footprint& body) {
  if (body.round) return {body.half_length, body.half_length};
  const double c = std::abs(std::cos(body.heading)), s = std::abs(std::sin(body.heading));
  return {body.half_length * c + body.half_width * s, body.half_length * s + body.half_width * c};
}

Bounds bounds_around(MapPoint centre, Reach reach) {
  return {centre.x - reach.x, centre.y - reach.y, centre.x + reach.x, centre.y + reach.y};
}

Bounds bounds_of(const Footprint& body) { return bounds_around(body.centre, reach_of(body)); }

// FCL bounds a turned shape by the cube around its bounding sphere (CollisionObject::computeAABB),
// 5.2 m wide for a car, which made cars in neighbouring lanes broadphase candidates at every
// step. Bodies only turn about z and all stand on the ground, so their footprint's bounds bound
// them exactly. A hair of margin keeps bodies that touch exactly candidates despite rounding.
SweepBox sweep_box_around(MapPoint centre, Reach reach) {
  constexpr double margin = 1e-9;
  const Bounds bounds = bounds_around(centre, reach);
  return {bounds.min_x - margin, bounds.min_y - margin, bounds.max_x + margin,
          bounds.max_y + margin};
}

bool overlap(const Bounds& a, const Bounds& b) {
  return a.min_x <= b.max_x && b.min_x <= a.max_x && a.min_y <= b.max_y && b.min_y <= a.max_y;
}

// The footprint's outline, counter-clockwise.
std::vector<MapPoint> outline(const Footprint& body) {
  std::vector<MapPoint> points;
  const double c = std::cos(body.heading), s = std::sin(body.heading);
  if (body.round) {
    const double step = 2 * std::numbers::pi / kDiscPolygonSides;
    const double circumradius = body.half_length / std::cos(step / 2);
    for (int i = 0; i < kDiscPolygonSides; ++i) {
      const double angle = body.heading + step * i;
      points.push_back({body.centre.x + circumradius * std::cos(angle),
                        body.centre.y + circumradius * std::sin(angle)});
    }
    return points;
  }
  const double corner_x[] = {1, -1, -1, 1}, corner_y[] = {1, 1, -1, -1};
  for (int i = 0; i < 4; ++i) {
    const double x = corner_x[i] * body.half_length, y = corner_y[i] * body.half_width;
    points.push_back({body.centre.x + x * c - y * s, body.centre.y + x * s + y * c});
  }
  return points;
}

double cross(MapPoint origin, MapPoint a, MapPoint b) {
  return (a.x - origin.x) * (b.y - origin.y) - (a.y - origin.y) * (b.x - origin.x);
}

// Sutherland-Hodgman: `subject` clipped by the convex, counter-clockwise `clip`.
std::vector<MapPoint> intersection(std::vector<MapPoint> subject,
                                   const std::vector<MapPoint>& clip) {
  std::vector<MapPoint> kept;
  for (std::size_t i = 0; i < clip.size() && !subject.empty(); ++i) {
    const MapPoint edge_start = clip[i], edge_end = clip[(i + 1) % clip.size()];
    kept.clear();
    for (std::size_t j = 0; j < subject.size(); ++j) {
      const MapPoint from = subject[j], to = subject[(j + 1) % subject.size()];
      const double side_from = cross(edge_start, edge_end, from);
      const double side_to = cross(edge_start, edge_end, to);
      if (side_from >= 0) kept.push_back(from);
      if ((side_from >= 0) != (side_to >= 0)) {
        const double t = side_from / (side_from - side_to);
        kept.push_back({from.x + t * (to.x - from.x), from.y + t * (to.y - from.y)});
      }
    }
    std::swap(subject, kept);
  }
  return subject;
}

// The centroid of where the footprints overlap. A touch has no area: then the mean of the
// touching points, and if rounding left nothing at all, halfway between the centres.
MapPoint local_contact_point(const Footprint& a, const Footprint& b) {
  const std::vector<MapPoint> shared = intersection(outline(a), outline(b));
  if (shared.empty()) return {(a.centre.x + b.centre.x) / 2, (a.centre.y + b.centre.y) / 2};
  double twice_area = 0, sum_x = 0, sum_y = 0;
  for (std::size_t i = 0; i < shared.size(); ++i) {
    const MapPoint p = shared[i], q = shared[(i + 1) % shared.size()];
    const double weight = p.x * q.y - q.x * p.y;
    twice_area += weight;
    sum_x += (p.x + q.x) * weight;
    sum_y += (p.y + q.y) * weight;
  }
  if (std::abs(twice_area) > 1e-12) return {sum_x / (3 * twice_area), sum_y / (3 * twice_area)};
  MapPoint mean;
  for (const MapPoint& p : shared) {
    mean.x += p.x / static_cast<double>(shared.size());
    mean.y += p.y / static_cast<double>(shared.size());
  }
  return mean;
}

// local_contact_point computed about a's centre: with map coordinates in the millions (UTM), the
// area formula's products would otherwise cancel catastrophically.
MapPoint contact_point(Footprint a, Footprint b) {
  const MapPoint origin = a.centre;
  a.centre = {0, 0};
  b.centre = {b.centre.x - origin.x, b.centre.y - origin.y};
  const MapPoint local = local_contact_point(a, b);
  return {origin.x + local.x, origin.y + local.y};
}

std::uint64_t pair_key(BodyId a, BodyId b) {
  const auto [low, high] = std::minmax(a, b);
  return (static_cast<std::uint64_t>(low) << 32) | high;
}

using BodyPair = std::pair<BodyId, BodyId>;

bool fcl_collide(const fcl::CollisionObjectd& a, const fcl::CollisionObjectd& b) {
  const fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(&a, &b, request, result);
  return result.isCollision();
}

}  // namespace

struct CollisionWorld::Impl {
  // A moving body's FCL transform is brought up to date only when the narrowphase needs it: most
  // steps most bodies are nowhere near another.
  struct Body {
    BodyGeometry geometry;
    MapPose pose;
    bool is_static = false;
    bool placed = true;  // object's transform is at pose
    // Of the footprint at reach_heading, a bound (turned_reach.hpp); kept while the heading
    // stays within kReachTurn of it (a car's heading drifts a little at every step).
    Reach reach;
    double reach_heading = 0;
    std::shared_ptr<fcl::CollisionGeometryd> shape;
    std::unique_ptr<fcl::CollisionObjectd> object;
  };

  std::vector<Body> bodies;
  std::vector<BodyId> static_bodies;
  std::vector<Bounds> static_bounds;  // parallel to static_bodies
  BodySweep sweep;
  std::unordered_set<std::uint64_t> ignored;  // pair_key of pairs find_contacts skips
  std::vector<BodyPair> candidates;
  std::vector<Contact> contacts;
  mutable std::atomic<std::uint64_t> narrowphase_checks{0};

  bool collide(const fcl::CollisionObjectd& a, const fcl::CollisionObjectd& b) const {
    narrowphase_checks.fetch_add(1, std::memory_order_relaxed);
    return fcl_collide(a, b);
  }

  // The body's reach at its pose's heading, as a bound: a disc's does not turn; a box's is bounded
  // without libm's sincos (turned_reach.hpp), and kept while the heading stays within kReachTurn
  // of the one it was taken at, widened by (half length + half width) x the turn since (|cos| and
  // |sin| change no faster than the angle). The sweep box only selects candidates for FCL, so a
  // little wider changes no contact.
  static Reach turned_reach(Body& body) {
    constexpr double kReachTurn = 0.01;  // rad: at most 3 cm wider on a car
    if (is_round(body.geometry.shape)) return body.reach;
    const double half_length = body.geometry.length / 2, half_width = body.geometry.width / 2;
    const double turn = std::abs(body.pose.heading - body.reach_heading);
    if (!(turn <= kReachTurn)) {
      const TurnedReach bound = turned_reach_bound(half_length, half_width, body.pose.heading);
      body.reach = {bound.x, bound.y};
      body.reach_heading = body.pose.heading;
      return body.reach;
    }
    // The turn allowance, and turned_reach_bound's relative margin over the exact reach.
    const double widening = (half_length + half_width) * (turn + 1e-9);
    return {body.reach.x + widening, body.reach.y + widening};
  }

  const fcl::CollisionObjectd& placed_object(Body& body) {
    if (!body.placed) {
      body.object->setTransform(transform_of(body.geometry, body.pose));
      body.placed = true;
    }
    return *body.object;
  }

  const Body& body(BodyId id) const {
    SCENFUZZ_DEMAND(id < bodies.size() && "no such body");
    return bodies[id];
  }
};

CollisionWorld::CollisionWorld() : impl_(std::make_unique<Impl>()) {}
CollisionWorld::CollisionWorld(CollisionWorld&&) noexcept = default;
CollisionWorld& CollisionWorld::operator=(CollisionWorld&&) noexcept = default;
CollisionWorld::~CollisionWorld() = default;

BodyId CollisionWorld::add_body(const BodyGeometry& geometry, const MapPose& pose, bool is_static) {
  check_geometry(geometry);
  check_pose(pose);
  const auto id = static_cast<BodyId>(impl_->bodies.size());
  std::shared_ptr<fcl::CollisionGeometryd> shape = make_shape(geometry);
  auto object = std::make_unique<fcl::CollisionObjectd>(shape, transform_of(geometry, pose));
  if (is_static) {
    impl_->static_bodies.push_back(id);
    impl_->static_bounds.push_back(bounds_of(footprint_of(geometry, pose)));
  }
  const Reach reach = reach_of(footprint_of(geometry, pose));
  impl_->sweep.add(sweep_box_around(pose.position, reach), is_static);
  impl_->bodies.push_back(
      {geometry, pose, is_static, true, reach, pose.heading, std::move(shape), std::move(object)});
  return id;
}

void CollisionWorld::set_pose(BodyId body, const MapPose& pose) {
  SCENFUZZ_DEMAND(body < impl_->bodies.size() && "no such body");
  Impl::Body& moving = impl_->bodies[body];
  SCENFUZZ_DEMAND(!moving.is_static && "a static body keeps the pose it was added with");
  check_pose(pose);
  moving.pose = pose;
  moving.placed = false;
  impl_->sweep.move(body, sweep_box_around(pose.position, Impl::turned_reach(moving)));
}

void CollisionWorld::set_enabled(BodyId body, bool enabled) {
  SCENFUZZ_DEMAND(body < impl_->bodies.size() && "no such body");
  impl_->sweep.set_enabled(body, enabled);
}

void CollisionWorld::ignore_pair(BodyId a, BodyId b) {
  SCENFUZZ_DEMAND(a < impl_->bodies.size() && b < impl_->bodies.size() && "no such body");
  impl_->ignored.insert(pair_key(a, b));
}

std::size_t CollisionWorld::body_count() const { return impl_->bodies.size(); }

Footprint CollisionWorld::footprint(BodyId body) const {
  const Impl::Body& found = impl_->body(body);
  return footprint_of(found.geometry, found.pose);
}

const std::vector<Contact>& CollisionWorld::find_contacts() {
  Impl& world = *impl_;
  world.sweep.overlapping_pairs(world.candidates);
  std::sort(world.candidates.begin(), world.candidates.end());

  world.contacts.clear();
  for (const auto& [first, second] : world.candidates) {
    if (!world.ignored.empty() && world.ignored.contains(pair_key(first, second))) continue;
    Impl::Body& a = world.bodies[first];
    Impl::Body& b = world.bodies[second];
    if (!world.collide(world.placed_object(a), world.placed_object(b))) continue;
    const Footprint footprint_a = footprint_of(a.geometry, a.pose);
    const Footprint footprint_b = footprint_of(b.geometry, b.pose);
    const MapPoint point = contact_point(footprint_a, footprint_b);
    world.contacts.push_back(
        {first, second, point, side_of(footprint_a, point), side_of(footprint_b, point)});
  }
  return world.contacts;
}

double CollisionWorld::distance(BodyId a, BodyId b) const {
  SCENFUZZ_DEMAND(a != b && "a body's distance to itself");
  const Impl::Body& body_a = impl_->body(a);
  const Impl::Body& body_b = impl_->body(b);
  // Objects at the bodies' current poses, built here: set_pose leaves transforms to
  // find_contacts, and a const query must not update them (it may run concurrently).
  const fcl::CollisionObjectd object_a(body_a.shape, transform_of(body_a.geometry, body_a.pose));
  const fcl::CollisionObjectd object_b(body_b.shape, transform_of(body_b.geometry, body_b.pose));
  const double footprint_distance = signed_distance(footprint_of(body_a.geometry, body_a.pose),
                                                    footprint_of(body_b.geometry, body_b.pose));
  // Footprints can overlap while the solids do not (a ball taller than a car, over its bonnet).
  if (footprint_distance <= 0 && impl_->collide(object_a, object_b)) return footprint_distance;

  fcl::DistanceRequestd request;
  request.gjk_solver_type = fcl::GST_INDEP;  // libccd's GJK is wrong at exact right angles
  fcl::DistanceResultd result;
  impl_->narrowphase_checks.fetch_add(1, std::memory_order_relaxed);
  fcl::distance(&object_a, &object_b, request, result);
  return std::max(result.min_distance, 0.0);
}

bool CollisionWorld::touches_static(const BodyGeometry& geometry, const MapPose& pose) const {
  check_geometry(geometry);
  check_pose(pose);
  const Bounds query_bounds = bounds_of(footprint_of(geometry, pose));
  std::optional<fcl::CollisionObjectd> query;  // built only when some bounds overlap
  for (std::size_t i = 0; i < impl_->static_bodies.size(); ++i) {
    if (!overlap(query_bounds, impl_->static_bounds[i])) continue;
    if (!query) query.emplace(make_shape(geometry), transform_of(geometry, pose));
    if (impl_->collide(*query, *impl_->bodies[impl_->static_bodies[i]].object)) return true;
  }
  return false;
}

std::uint64_t CollisionWorld::narrowphase_checks() const {
  return impl_->narrowphase_checks.load(std::memory_order_relaxed);
}

}  // namespace scenfuzz
