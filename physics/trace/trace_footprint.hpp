// The footprint of a traced actor at one sample: what distances between bodies are measured on.
#pragma once

#include <cstddef>

#include "physics/collision/footprint.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// Vehicles and box obstacles are oriented rectangles; pedestrians and round obstacles discs.
inline Footprint footprint_at(const Trace& trace, ActorId actor, std::size_t sample) {
  const TraceActor& a = trace.actors[actor];
  const bool round = a.shape != BodyShape::box;
  return {{a.x[sample], a.y[sample]}, a.heading[sample], a.length / 2, a.width / 2, round};
}

}  // namespace scenfuzz
