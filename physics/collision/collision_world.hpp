// The collision world: every body as an FCL shape (vehicles as boxes, pedestrians as cylinders,
// obstacles as the scenario's sphere, box, cone or cylinder), a sweep-and-prune broadphase over
// their footprints updated each step and FCL's narrowphase on its candidate pairs. FCL stays inside
// collision_world.cpp.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "physics/collision/body_side.hpp"
#include "physics/collision/footprint.hpp"
#include "physics/map/map_point.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

using BodyId = std::uint32_t;

// A body's size. Box: length along its heading, width across. Cylinder, sphere, cone: length
// and width are the diameter (both the same). All bodies stand on the ground (z from 0 up).
struct BodyGeometry {
  BodyShape shape = BodyShape::box;
  double length = 0;
  double width = 0;
  double height = 0;
};

struct Contact {
  BodyId first = 0;  // first < second
  BodyId second = 0;
  MapPoint point;  // where the two footprints overlap (the centre of their intersection)
  BodySide first_side = BodySide::front;
  BodySide second_side = BodySide::front;
};

class CollisionWorld {
 public:
  CollisionWorld();
  CollisionWorld(CollisionWorld&&) noexcept;
  CollisionWorld& operator=(CollisionWorld&&) noexcept;
  ~CollisionWorld();

  // Ids are handed out densely from 0 in the order bodies are added. A static body keeps the
  // pose it is added with; static bodies never collide with each other.
  BodyId add_body(const BodyGeometry& geometry, const MapPose& pose, bool is_static);
  void set_pose(BodyId body, const MapPose& pose);
  // A disabled body is not in the world for find_contacts: it touches nothing until enabled
  // again (a background-traffic vehicle before it enters the map and after it leaves). Bodies
  // are enabled when added.
  void set_enabled(BodyId body, bool enabled);
  std::size_t body_count() const;
  Footprint footprint(BodyId body) const;

  // Every pair of bodies in contact at the current poses, sorted by (first, second), except
  // the ignored pairs.
  const std::vector<Contact>& find_contacts();

  // find_contacts no longer tests or reports the pair (either order): a simulation records
  // only a pair's first contact, and scripted actors can overlap for many steps after it.
  void ignore_pair(BodyId a, BodyId b);

  // Footprint distance: FCL's distance when apart, 0 when touching, minus the penetration depth
  // (signed_distance of the footprints) when overlapping.
  double distance(BodyId a, BodyId b) const;

  // Whether a body of `geometry` at `pose` would touch any static body (path planning).
  bool touches_static(const BodyGeometry& geometry, const MapPose& pose) const;

  // Narrowphase tests run since construction (for the benchmark's checks per second).
  std::uint64_t narrowphase_checks() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace scenfuzz
