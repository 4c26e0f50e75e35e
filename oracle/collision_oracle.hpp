// The oracle for scenarios without specs: no collision of the ego. Its robustness is the smallest
// footprint distance between the ego and any other body over the run, negative (minus the
// penetration depth) on contact.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "physics/trace/trace.hpp"

namespace scenfuzz {

// At every sample, the footprint distance from the ego to the nearest other body (vehicles,
// pedestrians, obstacles); +inf when the ego is alone.
std::vector<double> ego_clearance(const Trace& trace);

struct CollisionVerdict {
  double robustness = 0;   // min of ego_clearance; +inf when the ego is alone
  std::size_t sample = 0;  // where the minimum is (the first such sample)
  ActorId other = kEgo;    // the body nearest there; kEgo when the ego is alone
};

CollisionVerdict collision_verdict(const Trace& trace);

// The same, but body k counts only before sample excused_from[k] (one entry per actor; the ego's
// is ignored): from its collision with the ego on, a body that collision was not the ego's fault
// for is left out, so the verdict is the ego's clearance up to that contact (>= 0).
CollisionVerdict collision_verdict(const Trace& trace, std::span<const std::size_t> excused_from);

}  // namespace scenfuzz
