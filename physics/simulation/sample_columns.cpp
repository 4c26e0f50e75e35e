// Recording the trace's samples by index (see sample_columns.hpp).
#include "physics/simulation/sample_columns.hpp"

#include <limits>

#include "lang/demand.hpp"

namespace scenfuzz {
namespace {

// Every column that size_sample_columns sizes, for each of its callers.
template <typename Visit>
void for_each_sized_column(Trace& trace, Visit visit) {
  for (TraceActor& actor : trace.actors) {
    visit(actor.x), visit(actor.y), visit(actor.heading), visit(actor.speed);
    visit(actor.acceleration), visit(actor.yaw_rate), visit(actor.lane), visit(actor.s);
    visit(actor.reversing);
  }
  for (PerceivedActor& perceived : trace.perceived) {
    visit(perceived.detected), visit(perceived.x), visit(perceived.y);
    visit(perceived.heading), visit(perceived.speed), visit(perceived.reversing);
  }
}

}  // namespace

void size_sample_columns(Trace& trace, std::size_t samples) {
  trace.time.reserve(samples);
  for_each_sized_column(trace, [&](auto& column) { column.resize(samples); });
  for (TraceActor& actor : trace.actors)
    if (actor.kind == TraceActorKind::ego || actor.kind == TraceActorKind::vehicle)
      actor.signals.reserve(samples);
  for (TraceLight& light : trace.lights) light.colour.reserve(samples);
}

void write_sample(TraceActor& actor, std::size_t i, const KinematicState& state, LaneFix lane) {
  SCENFUZZ_DEMAND(i < actor.x.size());
  actor.x[i] = state.x;
  actor.y[i] = state.y;
  actor.heading[i] = state.heading;
  actor.speed[i] = state.speed;
  actor.acceleration[i] = state.acceleration;
  actor.yaw_rate[i] = state.yaw_rate;
  actor.lane[i] = lane.lane;
  actor.s[i] = lane.s;
  actor.reversing[i] = state.reversing ? 1 : 0;
}

void write_perceived(PerceivedActor& column, std::size_t i, const WorldObject* seen) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  SCENFUZZ_DEMAND(i < column.x.size());
  column.detected[i] = seen ? 1 : 0;
  column.x[i] = seen ? seen->x : nan;
  column.y[i] = seen ? seen->y : nan;
  column.heading[i] = seen ? seen->heading : nan;
  column.speed[i] = seen ? seen->speed : nan;
  column.reversing[i] = seen && seen->reversing ? 1 : 0;
}

void trim_sample_columns(Trace& trace) {
  const std::size_t samples = trace.time.size();
  for_each_sized_column(trace, [&](auto& column) {
    SCENFUZZ_DEMAND(column.size() >= samples);
    column.resize(samples);
  });
}

}  // namespace scenfuzz
