// How far a rectangle turned by a heading reaches from its centre along x and along y, as an
// upper bound cheap enough to compute at every pose: the broadphase boxes of moving bodies come
// from it, and libm's sincos cost more than the rest of CollisionWorld::set_pose together.
#pragma once

namespace scenfuzz {

struct TurnedReach {
  double x = 0, y = 0;
};

// The exact reach is (h * |cos a| + w * |sin a|, h * |sin a| + w * |cos a|) for half extents h
// and w. This bound is at least that, as computed with std::cos and std::sin, and exceeds it by
// at most about 1e-9 * (h + w): a broadphase box from it holds every pair the exact box held.
TurnedReach turned_reach_bound(double half_length, double half_width, double heading);

}  // namespace scenfuzz
